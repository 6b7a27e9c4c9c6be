#include "block_command.hpp"

#include <cmath>

#include "ncbridge/common/error.hpp"

namespace ncbridge::interpreter {

namespace {

// Modal group of a G code (x10), -1 when unknown.
int g_group(int g) {
  switch (g) {
    case 40: case 53: case 100: case 280: case 281: case 300: case 301: case 520: case 530: case 920: case 921: case 922: case 923:
      return kGNonModal;
    case 0: case 10: case 20: case 30: case 50: case 51: case 52: case 330: case 331: case 382: case 383: case 384: case 385:
    case 730: case 740: case 760: case 800: case 810: case 820: case 830: case 840: case 850: case 860: case 870:
    case 880: case 890:
      return kGMotion;
    case 170: case 180: case 190: case 171: case 181: case 191: return kGPlane;
    case 900: case 910: return kGDistance;
    case 901: case 911: return kGArcDistance;
    case 930: case 940: case 950: return kGFeedMode;
    case 200: case 210: return kGUnits;
    case 400: case 410: case 420: case 411: case 421: return kGCutterComp;
    case 430: case 431: case 432: case 490: return kGToolLength;
    case 980: case 990: return kGRetract;
    case 540: case 550: case 560: case 570: case 580: case 590: case 591: case 592: case 593:
      return kGCoordSystem;
    case 610: case 611: case 640: return kGControl;
    case 960: case 970: return kGSpindleMode;
    case 70: case 80: return kGLatheDiameter;
    default: return -1;
  }
}

int m_group(int m) {
  switch (m) {
    case 0: case 1: case 2: case 30: case 60: return kMStop;
    case 66: return kMInput;
    case 6: case 61: return kMToolChange;
    case 3: case 4: case 5: case 19: case 70: case 71: case 72: case 73: return kMSpindle;
    case 7: case 8: case 9: return kMCoolant;
    case 48: case 49: case 50: case 51: case 52: case 53: return kMOverride;
    default: return (m >= 100 && m <= 199) ? kMUser : -1;
  }
}

}  // namespace

bool BlockCommand::has_axis() const {
  constexpr std::uint32_t axes = (1u << ('x' - 'a')) | (1u << ('y' - 'a')) | (1u << ('z' - 'a')) |
                                 (1u << ('a' - 'a')) | (1u << ('b' - 'a')) | (1u << ('c' - 'a')) |
                                 (1u << ('u' - 'a')) | (1u << ('v' - 'a')) | (1u << ('w' - 'a'));
  return (present & axes) != 0;
}

void BlockCommand::reset() {
  present = 0;
  g.fill(-1);
  m.fill(-1);
  g_column.fill(0);  // a modal code has no column in this block: errors then name the block's first
  m_column.fill(0);
  mist_on = flood_on = false;
  has_polar_radius = has_polar_angle = false;
  comment = {};
  comment_is_message = false;
  comment_action = CommentAction::Comment;
}

void assemble_command(const Block& block, const double* values, const std::string& file, BlockCommand& out) {
  out.reset();
  out.line = block.line;
  auto fail = [&](std::uint32_t column, const std::string& message) {
    throw InputError({file, block.line, column}, message);
  };
  for (std::size_t i = 0; i < block.words.size(); ++i) {
    const Word& w = block.words[i];
    double v = values[i];
    if (w.letter == 'g') {
      double scaled = v * 10.0;
      double rounded = std::nearbyint(scaled);
      if (std::fabs(scaled - rounded) > 1e-3 || rounded < 0 || rounded > 9999) {
        fail(w.column, "Unknown g code used");
      }
      int code = static_cast<int>(rounded);
      int group = g_group(code);
      if (group < 0) fail(w.column, "Unknown g code used: G" + std::to_string(code / 10) +
                                        (code % 10 ? "." + std::to_string(code % 10) : ""));
      if (out.g[static_cast<std::size_t>(group)] != -1) fail(w.column, "Two g codes used from same modal group");
      out.g[static_cast<std::size_t>(group)] = code;
      out.g_column[static_cast<std::size_t>(group)] = w.column;
    } else if (w.letter == 'm') {
      double rounded = std::nearbyint(v);
      if (std::fabs(v - rounded) > 1e-4 || rounded < 0 || rounded > 199) fail(w.column, "Unknown m code used");
      int code = static_cast<int>(rounded);
      int group = m_group(code);
      if (group < 0) fail(w.column, "Unknown m code used: M" + std::to_string(code));
      auto gi = static_cast<std::size_t>(group);
      if (group == kMCoolant && out.m[gi] != -1 && code != 9 && out.m[gi] != 9 && code != out.m[gi]) {
        // M7 and M8 together are allowed
      } else if (out.m[gi] != -1) {
        fail(w.column, "Two m codes used from same modal group");
      }
      if (code == 7) out.mist_on = true;
      if (code == 8) out.flood_on = true;
      out.m[gi] = code;
      out.m_column[gi] = w.column;
    } else if (w.letter == '@') {
      out.has_polar_radius = true;
      out.polar_radius = v;
      out.polar_radius_column = w.column;
    } else if (w.letter == '^') {
      out.has_polar_angle = true;
      out.polar_angle = v;
      out.polar_angle_column = w.column;
    } else {
      auto bit = static_cast<std::uint32_t>(w.letter - 'a');
      if ((out.present >> bit) & 1u) {
        fail(w.column, std::string("Multiple ") + static_cast<char>(w.letter - 'a' + 'A') + " words on one line");
      }
      out.present |= 1u << bit;
      out.value[bit] = v;
      out.column[bit] = w.column;
    }
  }
  for (const auto& c : block.comments) {
    if (c.kind == CommentText::Kind::LineEnd) continue;  // LinuxCNC does not report `;` comments
    out.comment = c.text;
    out.comment_is_message = c.kind == CommentText::Kind::Message;
  }
}

}  // namespace ncbridge::interpreter
