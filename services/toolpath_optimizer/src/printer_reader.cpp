// The printer front-end (printer_reader.hpp): one line at a time, state in a few fields.
#include "ncbridge/toolpath_optimizer/printer_reader.hpp"

#include <array>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>

#include "ncbridge/common/error.hpp"
#include "ncbridge/toolpath_optimizer/geometry.hpp"

namespace ncbridge::toolpath_optimizer {

namespace {

constexpr double kUnknown = std::numeric_limits<double>::quiet_NaN();

bool is_letter(char c) { return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z'); }
bool is_digit(char c) { return c >= '0' && c <= '9'; }
char upper(char c) { return c >= 'a' && c <= 'z' ? static_cast<char>(c - 'a' + 'A') : c; }

enum class ValueState : std::uint8_t { Number, Empty, Bad };

// No default member initialisers: a line's array of words is left uninitialised and each word
// is set whole when split_words finds it.
struct Word {
  char letter;
  ValueState state;
  double value;
  std::uint8_t decimals;
  bool glued;            // no number, and a letter right after (`Xabc`)
  std::uint32_t column;  // 1-based, of the letter
};

}  // namespace

bool parse_printer_flavor(std::string_view name, PrinterFlavor& flavor) {
  if (name == "marlin") flavor = PrinterFlavor::Marlin;
  else if (name == "reprap" || name == "reprapfirmware" || name == "rrf") flavor = PrinterFlavor::RepRapFirmware;
  else if (name == "klipper") flavor = PrinterFlavor::Klipper;
  else return false;
  return true;
}

std::string_view printer_flavor_name(PrinterFlavor flavor) {
  switch (flavor) {
    case PrinterFlavor::RepRapFirmware: return "reprap";
    case PrinterFlavor::Klipper: return "klipper";
    default: return "marlin";
  }
}

PrinterReader::PrinterReader(std::string file_name, PrinterFlavor flavor, ElementSink& sink)
    : file_(std::move(file_name)), flavor_(flavor), sink_(sink) {}

void PrinterReader::fail(std::size_t column, const std::string& message) const {
  throw InputError({file_, line_number_, static_cast<std::uint32_t>(column)}, message);
}

namespace {

// Splits the code part of a line into words: a letter and the number right after it (which may
// be empty: `G92 E`). Stops at a checksum `*`. Returns false when the line has more words than
// fit or something that is not a word (the caller decides whether that matters).
template <typename W, std::size_t N>
bool split_words(std::string_view code, std::array<W, N>& words, std::size_t& count, bool& checksum,
                 std::size_t& bad_column) {
  count = 0;
  checksum = false;
  bad_column = 0;
  std::size_t i = 0;
  while (i < code.size()) {
    const char c = code[i];
    if (c == ' ' || c == '\t' || c == '\r') {
      ++i;
      continue;
    }
    if (c == '*') {
      checksum = true;
      return true;
    }
    if (!is_letter(c)) {
      bad_column = i + 1;
      return false;
    }
    if (count == N) return false;
    W& w = words[count++];
    w = W{};
    w.letter = upper(c);
    w.column = static_cast<std::uint32_t>(i + 1);
    std::size_t j = ++i;
    if (j < code.size() && (code[j] == '+' || code[j] == '-')) ++j;
    const std::size_t digits_begin = j;
    while (j < code.size() && is_digit(code[j])) ++j;
    std::size_t fraction = 0;
    bool point = false;
    if (j < code.size() && code[j] == '.') {
      point = true;
      const std::size_t f0 = ++j;
      while (j < code.size() && is_digit(code[j])) ++j;
      fraction = j - f0;
    }
    const bool any_digit = (j - digits_begin) > (point ? 1u : 0u);
    const bool ends_well = j == code.size() || code[j] == ' ' || code[j] == '\t' || code[j] == '*' ||
                           code[j] == '\r' || is_letter(code[j]);
    if (j == i && ends_well) {
      w.state = ValueState::Empty;
      w.glued = j < code.size() && is_letter(code[j]);
    } else if (!any_digit || !ends_well) {
      w.state = ValueState::Bad;
      while (j < code.size() && code[j] != ' ' && code[j] != '\t' && code[j] != '*') ++j;
    } else if (const std::size_t digits = j - digits_begin - (point ? 1 : 0); digits <= 15) {
      // At most 15 digits: the digits as an integer and the power of ten are both exact doubles,
      // so one division rounds correctly (Clinger's fast path), as from_chars would.
      static constexpr double kPowers[] = {1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8,
                                           1e9, 1e10, 1e11, 1e12, 1e13, 1e14, 1e15};
      std::uint64_t mantissa = 0;
      for (std::size_t k = digits_begin; k < j; ++k) {
        if (code[k] != '.') mantissa = mantissa * 10 + static_cast<std::uint64_t>(code[k] - '0');
      }
      const double magnitude = static_cast<double>(mantissa) / kPowers[fraction];
      w.value = code[i] == '-' ? -magnitude : magnitude;
      w.state = ValueState::Number;
      w.decimals = static_cast<std::uint8_t>(std::min<std::size_t>(fraction, 12));
    } else {
      const char* first = code.data() + i + (code[i] == '+' ? 1 : 0);
      const auto result = std::from_chars(first, code.data() + j, w.value);
      w.state = result.ec == std::errc() ? ValueState::Number : ValueState::Bad;
      w.decimals = static_cast<std::uint8_t>(std::min<std::size_t>(fraction, 12));
    }
    i = j;
  }
  return true;
}

bool integer_code(const Word& w, int& code) {
  if (w.state != ValueState::Number || w.value != std::floor(w.value) || w.value < 0 || w.value > 100000) return false;
  code = static_cast<int>(w.value);
  return w.decimals == 0;
}

}  // namespace

void PrinterReader::line(std::string_view text) {
  ++line_number_;
  ++counts_.lines;
  counts_.bytes += text.size();
  std::string_view body = text;
  bool crlf = false;
  if (!body.empty() && body.back() == '\n') {
    body.remove_suffix(1);
    if (!body.empty() && body.back() == '\r') {
      body.remove_suffix(1);
      crlf = true;
    }
  }
  // Control characters other than tab, CR and form feed: one branch-free pass over the line,
  // the exact look only when it finds one of them or a tab.
  bool control = false;
  for (const char ch : body) {
    const auto c = static_cast<unsigned char>(ch);
    control |= (c < 0x20) | (c == 0x7f);
  }
  if (control) {
    for (std::size_t i = 0; i < body.size(); ++i) {
      const auto c = static_cast<unsigned char>(body[i]);
      if (c == 0 || (c < 0x20 && c != '\t' && c != '\r' && c != '\f') || c == 0x7f) {
        char hex[8];
        std::snprintf(hex, sizeof hex, "0x%02x", c);
        fail(i + 1, std::string("binary data (byte ") + hex + ") in a G-code line");
      }
    }
  }
  std::string_view code = body.substr(0, body.find(';'));
  const bool has_comment = code.size() != body.size();
  while (!code.empty() && (code.back() == ' ' || code.back() == '\t' || code.back() == '\r')) code.remove_suffix(1);
  std::size_t lead = 0;
  while (lead < code.size() && (code[lead] == ' ' || code[lead] == '\t')) ++lead;

  auto pass = [&](LineRole role) { sink_.element(Element{TextLine{std::string(text), line_number_, role}}); };
  if (lead == code.size()) {
    pass(has_comment ? LineRole::Comment : LineRole::Blank);
    return;
  }
  ++counts_.commands;

  std::array<Word, 24> words;  // uninitialised: split_words sets the first `count`
  std::size_t count = 0, bad_column = 0;
  bool checksum = false;
  const bool plain = split_words(code, words, count, checksum, bad_column);
  // The command word: the first G/M/T after an optional N line number.
  std::size_t first = 0;
  bool numbered = false;
  if (count > 0 && words[0].letter == 'N') {
    first = 1;
    numbered = true;
  }
  int number = -1;
  const bool command = first < count && integer_code(words[first], number);
  if (!command) {
    pass(LineRole::Command);  // Klipper macros, host commands, anything we do not read
    return;
  }
  const char letter = words[first].letter;
  if (letter == 'T') {
    pass(LineRole::ToolChange);
    return;
  }
  if (letter == 'M') {
    if (number == 82 || number == 83) {
      m83_ = number == 83;
      pass(LineRole::Setting);
      return;
    }
    pass(LineRole::Command);
    return;
  }
  if (letter != 'G') {
    pass(LineRole::Command);
    return;
  }
  if (!plain && number <= 3) fail(bad_column, "unexpected character in a motion line");

  // Modal G words other than the first (`G1 G91 X1` is legal, if rare) apply first.
  bool other_g = false;
  for (std::size_t i = first + 1; i < count; ++i) {
    int g = -1;
    if (words[i].letter != 'G') continue;
    other_g = true;
    if (!integer_code(words[i], g)) continue;
    if (g == 90 || g == 91) {
      relative_xyz_ = g == 91;
      if (flavor_ == PrinterFlavor::Marlin) m83_ = g == 91;
    } else if (g == 20 || g == 21) {
      inches_ = g == 20;
    }
  }

  if (number <= 3) {
    // Words of a motion: axes must carry numbers; F may be junk (Marlin ignores it).
    bool fixed = numbered || checksum || has_comment || other_g || relative_xyz_;
    bool has_xyz[3] = {false, false, false};
    double xyz[3] = {0, 0, 0};
    std::uint8_t xyz_decimals = 0, e_decimals = 0;
    bool has_e = false, has_f = false;
    double e = 0, f = 0, centre[3] = {0, 0, 0}, r = 0;
    bool has_centre[3] = {false, false, false}, has_r = false;
    std::uint32_t turns = 0;
    bool seen[26] = {};
    for (std::size_t i = first + 1; i < count; ++i) {
      const Word& w = words[i];
      if (w.letter == 'G') continue;
      if (seen[w.letter - 'A']) fixed = true;
      seen[w.letter - 'A'] = true;
      const bool numeric = w.state == ValueState::Number;
      const double v = numeric ? w.value : 0.0;  // a letter without a number means 0 (Marlin)
      if (w.state == ValueState::Empty) fixed = true;
      if (w.glued && std::string_view("XYZEIJKR").find(w.letter) != std::string_view::npos) {
        fail(w.column, std::string(1, w.letter) + " word without a valid number");
      }
      switch (w.letter) {
        case 'X': case 'Y': case 'Z': {
          if (w.state == ValueState::Bad) fail(w.column, std::string(1, w.letter) + " word without a valid number");
          const int axis = w.letter - 'X';
          has_xyz[axis] = true;
          xyz[axis] = v;
          xyz_decimals = std::max(xyz_decimals, w.decimals);
          break;
        }
        case 'E':
          if (w.state == ValueState::Bad) fail(w.column, "E word without a valid number");
          has_e = true;
          e = v;
          e_decimals = w.decimals;
          break;
        case 'F':
          if (numeric && v > 0) {
            has_f = true;
            f = v;
          } else {
            fixed = true;
          }
          break;
        case 'I': case 'J': case 'K':
          if (w.state == ValueState::Bad) fail(w.column, std::string(1, w.letter) + " word without a valid number");
          has_centre[w.letter - 'I'] = true;
          centre[w.letter - 'I'] = v;
          if (number <= 1) fixed = true;
          break;
        case 'R':
          if (w.state == ValueState::Bad) fail(w.column, "R word without a valid number");
          has_r = true;
          r = v;
          if (number <= 1) fixed = true;
          break;
        case 'P':
          if (number >= 2 && numeric && v >= 1 && v == std::floor(v) && v < 1000) turns = static_cast<std::uint32_t>(v) - 1;
          fixed = true;
          break;
        default:
          fixed = true;  // S (laser power), H, A/B/C ...: kept as written
          break;
      }
    }
    if (has_f) feed_ = f;
    Motion m;
    m.kind = number == 0 ? MotionKind::Traverse : number == 1 ? MotionKind::Line : MotionKind::Arc;
    m.start = position_;
    Vec3 end = position_;
    double* axes[3] = {&end.x, &end.y, &end.z};
    for (int a = 0; a < 3; ++a) {
      if (has_xyz[a]) *axes[a] = relative_xyz_ ? *axes[a] + xyz[a] : xyz[a];
    }
    m.end = end;
    const bool relative_e = flavor_ == PrinterFlavor::RepRapFirmware ? m83_
                            : flavor_ == PrinterFlavor::Klipper     ? (m83_ || relative_xyz_)
                                                                     : m83_;
    if (has_e) {
      m.extrusion = relative_e ? e : e - e_position_;
      e_position_ = relative_e ? e_position_ + e : e;
      if (std::isnan(m.extrusion)) m.extrusion = 0;  // E after an unknown E position: not measurable
    }
    m.feed = feed_;
    m.units = inches_ ? canonical::Units::Inches : canonical::Units::Millimeters;
    m.source.line = line_number_;
    m.start_known = !std::isnan(m.start.x) && !std::isnan(m.start.y) && !std::isnan(m.start.z) &&
                    !std::isnan(m.end.x) && !std::isnan(m.end.y) && !std::isnan(m.end.z);
    m.arc.plane = plane_;
    if (m.kind == MotionKind::Arc) {
      m.arc.ccw = number == 3;
      m.arc.extra_turns = turns;
      const PlanePoint s = to_plane(m.start, plane_), t = to_plane(m.end, plane_);
      // Offsets of the plane's first and second axes: XY: I J; YZ: J K; XZ: K I.
      const int fi = plane_ == canonical::Plane::YZ ? 1 : plane_ == canonical::Plane::XZ ? 2 : 0;
      const int si = plane_ == canonical::Plane::YZ ? 2 : plane_ == canonical::Plane::XZ ? 0 : 1;
      if (has_r && !has_centre[fi] && !has_centre[si]) {
        // R form: the centre left (G3) or right (G2) of the chord; R < 0 takes the long way.
        const double dx = t.first - s.first, dy = t.second - s.second;
        const double chord = std::hypot(dx, dy);
        const double half = chord / 2;
        if (chord == 0 || std::abs(r) < half - 1e-9) {
          fail(words[first].column, "arc radius R is shorter than half the chord");
        }
        const double h = std::sqrt(std::max(0.0, r * r - half * half));
        double side = m.arc.ccw ? 1.0 : -1.0;
        if (r < 0) side = -side;
        m.arc.first_centre = s.first + dx / 2 - side * h * dy / chord;
        m.arc.second_centre = s.second + dy / 2 + side * h * dx / chord;
      } else if (has_centre[fi] || has_centre[si]) {
        m.arc.first_centre = s.first + centre[fi];
        m.arc.second_centre = s.second + centre[si];
      } else {
        fail(words[first].column, "arc without I/J/K or R");
      }
      ++counts_.arcs;
      fixed = true;
    }
    (void)has_r;
    if (!has_xyz[0] && !has_xyz[1] && !has_xyz[2] && !has_e && m.kind != MotionKind::Arc) {
      // `G1 F1800` or a bare `G1`: sets the mode and feed, moves nothing.
      ++counts_.motion_blocks;
      pass(LineRole::MotionMode);
      return;
    }
    ++counts_.motion_blocks;
    m.printer.text = std::string(text);
    m.printer.e_position = e_position_;
    m.printer.xyz_decimals = xyz_decimals;
    m.printer.e_decimals = e_decimals;
    m.printer.relative_e = relative_e;
    m.printer.relative_xyz = relative_xyz_;
    m.printer.has_e = has_e;
    m.printer.has_f = has_f;
    m.printer.crlf = crlf;
    m.keep = fixed || !m.start_known;
    position_ = end;
    sink_.element(Element{std::move(m)});
    return;
  }

  switch (number) {
    case 90: case 91:
      relative_xyz_ = number == 91;
      if (flavor_ == PrinterFlavor::Marlin) m83_ = number == 91;
      pass(LineRole::Setting);
      return;
    case 20: case 21:
      inches_ = number == 20;
      pass(LineRole::Setting);
      return;
    case 17: plane_ = canonical::Plane::XY; pass(LineRole::Setting); return;
    case 18: plane_ = canonical::Plane::XZ; pass(LineRole::Setting); return;
    case 19: plane_ = canonical::Plane::YZ; pass(LineRole::Setting); return;
    case 92: {
      for (std::size_t i = first + 1; i < count; ++i) {
        const Word& w = words[i];
        if (w.state == ValueState::Bad && (w.letter == 'X' || w.letter == 'Y' || w.letter == 'Z' || w.letter == 'E')) {
          fail(w.column, std::string(1, w.letter) + " word without a valid number");
        }
        const double v = w.state == ValueState::Number ? w.value : 0.0;
        if (w.letter == 'X') position_.x = v;
        else if (w.letter == 'Y') position_.y = v;
        else if (w.letter == 'Z') position_.z = v;
        else if (w.letter == 'E') e_position_ = v;
      }
      pass(LineRole::Setting);
      return;
    }
    case 28: case 29: {
      // Homing (or probing): where the head ends up is the firmware's business.
      bool any = false;
      for (std::size_t i = first + 1; i < count; ++i) {
        const char l = words[i].letter;
        if (l == 'X') position_.x = kUnknown, any = true;
        else if (l == 'Y') position_.y = kUnknown, any = true;
        else if (l == 'Z') position_.z = kUnknown, any = true;
      }
      if (!any || number == 29) position_ = {kUnknown, kUnknown, kUnknown};
      pass(LineRole::Homing);
      return;
    }
    default:
      pass(LineRole::Command);  // G4 dwell, G10/G11 firmware retraction, ...
      return;
  }
}

void PrinterReader::text(std::string_view piece) {
  std::size_t begin = 0;
  if (!pending_.empty()) {
    const std::size_t nl = piece.find('\n');
    if (nl == std::string_view::npos) {
      pending_.append(piece);
      return;
    }
    pending_.append(piece.substr(0, nl + 1));
    line(pending_);
    pending_.clear();
    begin = nl + 1;
  }
  for (;;) {
    const std::size_t nl = piece.find('\n', begin);
    if (nl == std::string_view::npos) break;
    line(piece.substr(begin, nl + 1 - begin));
    begin = nl + 1;
  }
  pending_.append(piece.substr(begin));
}

void PrinterReader::finish() {
  if (!pending_.empty()) {
    line(pending_);
    pending_.clear();
  }
  sink_.end();
}

PrinterCounts read_printer_text(std::string_view text, const std::string& name, PrinterFlavor flavor,
                                ElementSink& sink) {
  PrinterReader reader(name, flavor, sink);
  for_each_line(text, [&](std::string_view line) { reader.line(line); });
  reader.finish();
  return reader.counts();
}

PrinterCounts read_printer_file(const std::filesystem::path& path, PrinterFlavor flavor, ElementSink& sink) {
  const std::string name = path.string();
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(name.c_str(), "rb"), &std::fclose);
  if (!file) throw InputError({name, 0, 0}, "cannot open the file");
  PrinterReader reader(name, flavor, sink);
  constexpr std::size_t kChunk = 1 << 20;
  constexpr std::size_t kLongestLine = 16 << 20;
  std::string buffer;
  buffer.reserve(2 * kChunk);
  std::size_t begin = 0;
  for (;;) {
    // Keep the unfinished line, read the next chunk after it.
    buffer.erase(0, begin);
    begin = 0;
    const std::size_t kept = buffer.size();
    buffer.resize(kept + kChunk);
    const std::size_t got = std::fread(buffer.data() + kept, 1, kChunk, file.get());
    buffer.resize(kept + got);
    if (got == 0) {
      if (std::ferror(file.get())) throw InputError({name, 0, 0}, "read error");
      break;
    }
    const std::string_view view(buffer);
    for (;;) {
      const std::size_t nl = view.find('\n', begin);
      if (nl == std::string_view::npos) break;
      reader.line(view.substr(begin, nl + 1 - begin));
      begin = nl + 1;
    }
    if (buffer.size() - begin > kLongestLine) {
      throw InputError({name, static_cast<std::uint32_t>(reader.counts().lines + 1), 0}, "a line longer than 16 MiB: not G-code");
    }
  }
  if (begin < buffer.size()) reader.line(std::string_view(buffer).substr(begin));
  reader.finish();
  return reader.counts();
}

}  // namespace ncbridge::toolpath_optimizer
