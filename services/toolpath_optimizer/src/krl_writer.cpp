// KUKA KRL writer (krl.hpp).
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "ncbridge/common/error.hpp"
#include "ncbridge/interpreter/canon_printer.hpp"
#include "ncbridge/toolpath_optimizer/geometry.hpp"
#include "ncbridge/toolpath_optimizer/krl.hpp"
#include "ncbridge/toolpath_optimizer/number_text.hpp"

namespace ncbridge::toolpath_optimizer {

namespace {

bool known(const Vec3& p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); }

std::string trim_line_end(std::string_view text) {
  while (!text.empty() && (text.back() == '\n' || text.back() == '\r')) text.remove_suffix(1);
  std::string out(text);
  for (char& c : out) {
    if (c == '\r' || c == '\n') c = ' ';
  }
  return out;
}

std::string real(double v, int decimals) {
  std::string s;
  append_number(s, v, decimals);
  return s;
}

}  // namespace

std::string krl_module_name(std::string_view stem) {
  std::string name;
  for (char c : stem) {
    if (std::isalnum(static_cast<unsigned char>(c))) name.push_back(static_cast<char>(std::toupper(static_cast<unsigned char>(c))));
    else if (!name.empty() && name.back() != '_') name.push_back('_');
  }
  while (!name.empty() && name.back() == '_') name.pop_back();
  if (name.empty() || !std::isalpha(static_cast<unsigned char>(name[0]))) name = "P" + name;
  if (name.size() > 24) name.resize(24);
  return name;
}

KrlWriter::KrlWriter(const KrlOptions& options, std::function<void(std::string_view)> src,
                     std::function<void(std::string_view)> dat)
    : o_(options), src_(std::move(src)), dat_(std::move(dat)) {
  buffer_.reserve(1 << 16);
  line(0, "&ACCESS RVP", false);
  line(0, "&REL 1", false);
  line(0, "DEF " + o_.name + "( )", false);
  line(1, "; written by ncbridge optimize" + (o_.source.empty() ? std::string() : " from " + o_.source) +
              " (docs/krl.md)", false);
  line(1, "; BASE_DATA[" + std::to_string(o_.base) + "]: the part's frame; TOOL_DATA[" + std::to_string(o_.tool) +
              "]: the tool tip; lengths in mm", false);
  line(1, "BAS(#INITMOV, 0)");
  line(1, "$BASE = BASE_DATA[" + std::to_string(o_.base) + "]");
  line(1, "$TOOL = TOOL_DATA[" + std::to_string(o_.tool) + "]");
  line(1, "$APO.CDIS = " + real(o_.approximation_mm, 4));
  line(1, "PTP NCB_HOME");
  ++motions_;
}

void KrlWriter::line(int depth, std::string_view text, bool statement) {
  buffer_.append(static_cast<std::size_t>(depth) * 2, ' ');
  buffer_.append(text);
  buffer_.push_back('\n');
  ++lines_;
  if (statement) ++commands_;
  if (buffer_.size() >= (1 << 16)) flush();
}

void KrlWriter::flush() {
  if (buffer_.empty()) return;
  src_(buffer_);
  buffer_.clear();
}

void KrlWriter::position(std::string& out, const Vec3& p, double scale, bool full) {
  out.append("{X ");
  append_number(out, p.x * scale, o_.decimals);
  out.append(", Y ");
  append_number(out, p.y * scale, o_.decimals);
  out.append(", Z ");
  append_number(out, p.z * scale, o_.decimals);
  if (full) {
    out.append(", A ");
    append_number(out, o_.orientation[0], 4);
    out.append(", B ");
    append_number(out, o_.orientation[1], 4);
    out.append(", C ");
    append_number(out, o_.orientation[2], 4);
  }
  out.push_back('}');
}

void KrlWriter::motion(const Motion& m, int depth) {
  const double scale = m.units == canonical::Units::Inches ? 25.4 : 1.0;
  std::string text;
  if (!known(m.end)) {
    line(depth, "; not written, from and to a position not known after homing: " +
                    (m.printer.text.empty() ? std::string("a move") : trim_line_end(m.printer.text)), false);
    return;
  }
  const bool zero_length = m.kind != MotionKind::Arc && m.start == m.end;
  if (zero_length) {
    if (m.extrusion != 0 && o_.extruder) {
      line(depth, "NCB_FILAMENT(" + real(m.extrusion * scale, 5) + ", " + real(m.feed * scale, 3) + ")");
    }
    return;
  }
  if (!m.start_known || !known_) {
    // The robot goes to the first point it knows by PTP, with the tool's orientation.
    text = "PTP ";
    position(text, m.start_known ? m.start : m.end, scale, true);
    line(depth, text);
    ++motions_;
    known_ = true;
    if (!m.start_known) return;
  }
  const double feed = m.feed > 0 ? m.feed * scale : -2;
  if (feed != feed_) {
    const double v = feed > 0 ? feed / 60000 : o_.rapid_m_per_s;
    line(depth, "$VEL.CP = " + real(v, 6));
    feed_ = feed;
  }
  // An arc too flat for its three written points to tell a circle from a line goes as a LIN
  // (it strays from the line by less than the writing resolution).
  bool as_line = m.kind != MotionKind::Arc;
  ArcPath arc;
  if (!as_line) {
    arc = resolve_arc(m);
    if (arc.end_normal != arc.start_normal || m.arc.extra_turns > 0) {
      throw InputError({o_.source, m.source.line, 0},
                       "a helical or multi-turn arc has no KRL equivalent (CIRC is a plane circle of at most one turn)");
    }
    const double half = std::min(std::abs(arc.sweep), kPi) / 2;
    const double sagitta = arc.start_radius * (1 - std::cos(half));
    as_line = sagitta * scale < 4 * std::pow(10.0, -o_.decimals);
  }
  if (o_.extruder) {
    const double length = as_line ? distance(m.start, m.end) : path_length(m);
    const double rate = length > 0 ? m.extrusion / length : 0;
    if (std::abs(rate - rate_) > 1e-9) {
      line(depth, "TRIGGER WHEN DISTANCE=0 DELAY=0 DO NCB_EXTRUDE=" + real(rate, 7));
      rate_ = rate;
    }
  }
  if (as_line) {
    text = "LIN ";
    position(text, m.end, scale, false);
    text += " C_DIS";
    line(depth, text);
    ++motions_;
    return;
  }
  const bool full = std::abs(std::abs(arc.sweep) - 2 * kPi) < 1e-9;
  text = "CIRC ";
  position(text, arc.at(full ? 1.0 / 3 : 0.5), scale, false);
  text += ", ";
  position(text, full ? arc.at(2.0 / 3) : m.end, scale, false);
  text += full ? ", CA 360 C_DIS" : " C_DIS";
  line(depth, text);
  ++motions_;
}

void KrlWriter::write(const Element& e, int depth) {
  if (const auto* m = std::get_if<Motion>(&e.item)) {
    motion(*m, depth);
  } else if (const auto* t = std::get_if<TextLine>(&e.item)) {
    if (t->role == LineRole::Blank) return;
    const std::string text = trim_line_end(t->text);
    if (t->role == LineRole::Homing) {
      line(depth, "PTP NCB_HOME ; " + text);
      ++motions_;
      known_ = false;
      return;
    }
    line(depth, text[0] == ';' ? text : "; " + text, false);
  } else if (const auto* c = std::get_if<canonical::Call>(&e.item)) {
    std::string text;
    if (const auto* comment = std::get_if<canonical::Comment>(&c->data)) text = comment->text;
    else interpreter::CanonPrinter::format_call(c->data, text);
    line(depth, "; " + trim_line_end(text), false);
  } else if (const auto* loop = std::get_if<Loop>(&e.item)) {
    const double scale = [&] {
      for (const auto& inner : loop->body) {
        if (const auto* first = std::get_if<Motion>(&inner.item)) return first->units == canonical::Units::Inches ? 25.4 : 1.0;
      }
      return 1.0;
    }();
    line(depth, "NCB_ZOFF.Z = 0");
    line(depth, "FOR NCB_LAYER = 1 TO " + std::to_string(loop->count));
    line(depth + 1, "$BASE = BASE_DATA[" + std::to_string(o_.base) + "] : NCB_ZOFF");
    // Each time round starts from what the body leaves: state the feed and the extrusion anew.
    feed_ = -1;
    rate_ = -1;
    for (const auto& inner : loop->body) write(inner, depth + 1);
    line(depth + 1, "NCB_ZOFF.Z = NCB_ZOFF.Z + " + real(loop->z_shift * scale, o_.decimals + 2));
    line(depth, "ENDFOR");
    line(depth, "$BASE = BASE_DATA[" + std::to_string(o_.base) + "]");
  }
}

void KrlWriter::element(Element&& e) { write(e, 1); }

void KrlWriter::end() {
  line(1, "PTP NCB_HOME");
  ++motions_;
  line(0, "END", false);
  if (o_.extruder) {
    line(0, "", false);
    line(0, "DEF NCB_FILAMENT(LENGTH:IN, FEED:IN)", false);
    line(1, "; A filament-only move (retraction, prime) while the robot stands: the extruder's control", false);
    line(1, "; moves NCB_FILAMENT_MOVE mm at NCB_FILAMENT_FEED mm/min and clears NCB_FILAMENT_BUSY.", false);
    line(1, "REAL LENGTH, FEED", false);
    line(1, "NCB_FILAMENT_MOVE = LENGTH");
    line(1, "NCB_FILAMENT_FEED = FEED");
    line(1, "NCB_FILAMENT_BUSY = TRUE");
    line(1, "WAIT FOR NOT NCB_FILAMENT_BUSY");
    line(0, "END", false);
  }
  flush();
  std::string dat;
  dat += "&ACCESS RVP\n&REL 1\n";
  dat += "DEFDAT " + o_.name + " PUBLIC\n";
  dat += "  ; declarations of " + o_.name + ".SRC, written by ncbridge optimize (docs/krl.md)\n";
  dat += "  DECL E6AXIS NCB_HOME={A1 " + real(o_.home[0], 4) + ", A2 " + real(o_.home[1], 4) + ", A3 " +
         real(o_.home[2], 4) + ", A4 " + real(o_.home[3], 4) + ", A5 " + real(o_.home[4], 4) + ", A6 " +
         real(o_.home[5], 4) + ", E1 0, E2 0, E3 0, E4 0, E5 0, E6 0}\n";
  dat += "  DECL INT NCB_LAYER=0\n";
  dat += "  DECL FRAME NCB_ZOFF={X 0, Y 0, Z 0, A 0, B 0, C 0}\n";
  if (o_.extruder) {
    dat += "  DECL GLOBAL REAL NCB_EXTRUDE=0\n";
    dat += "  DECL GLOBAL REAL NCB_FILAMENT_MOVE=0\n";
    dat += "  DECL GLOBAL REAL NCB_FILAMENT_FEED=0\n";
    dat += "  DECL GLOBAL BOOL NCB_FILAMENT_BUSY=FALSE\n";
  }
  dat += "ENDDAT\n";
  dat_(dat);
}

}  // namespace ncbridge::toolpath_optimizer
