// The KRL reader (krl.hpp): the subset KrlWriter writes, statement by statement, FOR loops run out.
#include <cctype>
#include <charconv>
#include <cmath>
#include <optional>
#include <vector>

#include "ncbridge/common/error.hpp"
#include "ncbridge/toolpath_optimizer/geometry.hpp"
#include "ncbridge/toolpath_optimizer/krl.hpp"

namespace ncbridge::toolpath_optimizer {

namespace {

struct Line {
  std::string upper;         // the statement in upper case, comment and outer white space removed
  std::uint32_t number = 0;  // 1-based
  std::uint32_t column = 0;  // of the statement's first character
};

constexpr std::uint64_t kMaxIterations = 10'000'000;

class Reader {
 public:
  Reader(const std::string& name, ElementSink& sink) : name_(name), sink_(sink) {}

  void run(const std::vector<Line>& lines, std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) {
      const Line& l = lines[i];
      if (l.upper == "ENDFOR") fail(l, 1, "ENDFOR without FOR");
      if (starts(l.upper, "FOR ")) {
        const std::size_t close = matching_endfor(lines, i, end);
        const std::uint64_t count = for_count(l);
        ++counts.loops;
        if ((iterations_ += count) > kMaxIterations) fail(l, 1, "loops run more than 10 million times");
        const bool counting = counted_;
        for (std::uint64_t k = 0; k < count; ++k) {
          counted_ = counting && k == 0;  // a body's statements count once, as written
          run(lines, i + 1, close);
        }
        counted_ = counting;
        i = close;
        continue;
      }
      statement(l);
    }
  }

  std::size_t matching_endfor(const std::vector<Line>& lines, std::size_t at, std::size_t end) {
    int depth = 0;
    for (std::size_t i = at; i < end; ++i) {
      if (starts(lines[i].upper, "FOR ")) ++depth;
      else if (lines[i].upper == "ENDFOR" && --depth == 0) return i;
    }
    fail(lines[at], 1, "FOR without ENDFOR");
  }

  KrlCounts counts;

 private:
  static bool starts(const std::string& s, std::string_view prefix) { return s.compare(0, prefix.size(), prefix) == 0; }

  [[noreturn]] void fail(const Line& l, std::size_t at, const std::string& message) const {
    throw InputError({name_, l.number, static_cast<std::uint32_t>(l.column + at - 1)}, message);
  }

  double number(const Line& l, std::string_view text, std::size_t& pos) const {
    while (pos < text.size() && text[pos] == ' ') ++pos;
    const std::size_t begin = pos;
    if (pos < text.size() && (text[pos] == '+' || text[pos] == '-')) ++pos;
    while (pos < text.size() && (std::isdigit(static_cast<unsigned char>(text[pos])) || text[pos] == '.')) ++pos;
    double v = 0;
    const char* first = text.data() + begin + (text[begin] == '+' ? 1 : 0);
    const auto r = std::from_chars(first, text.data() + pos, v);
    if (r.ec != std::errc() || r.ptr != text.data() + pos || !std::isfinite(v)) fail(l, begin + 1, "a number expected");
    return v;
  }

  void expect(const Line& l, std::string_view text, std::size_t& pos, char c) const {
    while (pos < text.size() && text[pos] == ' ') ++pos;
    if (pos >= text.size() || text[pos] != c) fail(l, pos + 1, std::string("'") + c + "' expected");
    ++pos;
  }

  // {X 1, Y 2, Z 3[, A .., B .., C ..]}: missing X/Y/Z keep the current position's.
  Vec3 aggregate(const Line& l, std::size_t& pos, bool& complete) {
    const std::string& t = l.upper;
    expect(l, t, pos, '{');
    Vec3 p = position_;
    bool seen[3] = {false, false, false};
    for (;;) {
      while (pos < t.size() && t[pos] == ' ') ++pos;
      if (pos >= t.size()) fail(l, pos + 1, "'}' expected");
      std::size_t name_end = pos;
      while (name_end < t.size() && std::isalnum(static_cast<unsigned char>(t[name_end]))) ++name_end;
      const std::string component = t.substr(pos, name_end - pos);
      if (component.empty()) fail(l, pos + 1, "a component name expected");
      pos = name_end;
      const double v = number(l, t, pos);
      if (component == "X") p.x = v, seen[0] = true;
      else if (component == "Y") p.y = v, seen[1] = true;
      else if (component == "Z") p.z = v, seen[2] = true;
      else if (component != "A" && component != "B" && component != "C") fail(l, name_end - component.size() + 1, "component " + component + " is not read");
      while (pos < t.size() && t[pos] == ' ') ++pos;
      if (pos < t.size() && t[pos] == ',') {
        ++pos;
        continue;
      }
      expect(l, t, pos, '}');
      break;
    }
    complete = seen[0] && seen[1] && seen[2];
    p.z += base_shift_ * (seen[2] ? 1 : 0);
    if (!seen[2]) p.z = position_.z;
    return p;
  }

  void end_of_statement(const Line& l, std::size_t pos, bool c_dis_allowed) {
    while (pos < l.upper.size() && l.upper[pos] == ' ') ++pos;
    if (c_dis_allowed && l.upper.compare(pos, 5, "C_DIS") == 0) pos += 5;
    while (pos < l.upper.size() && l.upper[pos] == ' ') ++pos;
    if (pos != l.upper.size()) fail(l, pos + 1, "unexpected text after the statement");
  }

  void emit(Motion&& m) {
    if (counted_) ++counts.motion_statements;
    sink_.element(Element{std::move(m)});
  }

  void statement(const Line& l) {
    const std::string& t = l.upper;
    std::size_t pos = 0;
    if (starts(t, "LIN ") || starts(t, "LIN{")) {
      pos = 3;
      bool complete = false;
      const Vec3 end = aggregate(l, pos, complete);
      end_of_statement(l, pos, true);
      if (!known_) fail(l, 1, "LIN from a position not known (no PTP to a point before it)");
      Motion m;
      m.kind = MotionKind::Line;
      m.start = position_;
      m.end = end;
      finish_motion(m);
      return;
    }
    if (starts(t, "CIRC ") || starts(t, "CIRC{")) {
      pos = 4;
      bool complete = false;
      const Vec3 aux = aggregate(l, pos, complete);
      expect(l, t, pos, ',');
      const Vec3 end = aggregate(l, pos, complete);
      double ca = 0;
      while (pos < t.size() && t[pos] == ' ') ++pos;
      if (pos < t.size() && t[pos] == ',') {
        ++pos;
        while (pos < t.size() && t[pos] == ' ') ++pos;
        if (t.compare(pos, 2, "CA") != 0) fail(l, pos + 1, "CA expected");
        pos += 2;
        ca = number(l, t, pos);
        if (std::abs(std::abs(ca) - 360) > 1e-9) fail(l, pos, "only CA 360 (a full circle) is read");
      }
      end_of_statement(l, pos, true);
      if (!known_) fail(l, 1, "CIRC from a position not known (no PTP to a point before it)");
      circ(l, aux, end, ca);
      return;
    }
    if (starts(t, "PTP ")) {
      pos = 4;
      while (pos < t.size() && t[pos] == ' ') ++pos;
      if (t.compare(pos, 8, "NCB_HOME") == 0) {
        end_of_statement(l, pos + 8, true);
        if (counted_) ++counts.motion_statements;
        known_ = false;
        return;
      }
      bool complete = false;
      const Vec3 end = aggregate(l, pos, complete);
      end_of_statement(l, pos, true);
      if (!complete && !known_) fail(l, 5, "PTP to a partly given point from an unknown position");
      Motion m;
      m.kind = MotionKind::Traverse;
      m.start = position_;
      m.end = end;
      m.start_known = false;  // a joint move: its path is the robot's business
      if (counted_) ++counts.motion_statements;
      sink_.element(Element{std::move(m)});
      position_ = end;
      known_ = true;
      return;
    }
    if (starts(t, "$VEL.CP")) {
      pos = 7;
      expect(l, t, pos, '=');
      const double v = number(l, t, pos);
      end_of_statement(l, pos, false);
      if (!(v > 0)) fail(l, 1, "$VEL.CP must be positive");
      feed_ = v * 60000;
      return;
    }
    if (starts(t, "TRIGGER WHEN DISTANCE=0 DELAY=0 DO NCB_EXTRUDE")) {
      pos = std::string_view("TRIGGER WHEN DISTANCE=0 DELAY=0 DO NCB_EXTRUDE").size();
      expect(l, t, pos, '=');
      rate_ = number(l, t, pos);
      end_of_statement(l, pos, false);
      return;
    }
    if (starts(t, "NCB_FILAMENT(")) {
      pos = 13;
      const double length = number(l, t, pos);
      expect(l, t, pos, ',');
      const double feed = number(l, t, pos);
      expect(l, t, pos, ')');
      end_of_statement(l, pos, false);
      if (!known_) fail(l, 1, "a filament move from a position not known");
      Motion m;
      m.kind = MotionKind::Line;
      m.start = m.end = position_;
      m.extrusion = length;
      m.feed = feed;
      if (counted_) ++counts.motion_statements;
      sink_.element(Element{std::move(m)});
      return;
    }
    if (starts(t, "NCB_ZOFF.Z")) {
      pos = 10;
      expect(l, t, pos, '=');
      while (pos < t.size() && t[pos] == ' ') ++pos;
      if (t.compare(pos, 10, "NCB_ZOFF.Z") == 0) {
        pos += 10;
        while (pos < t.size() && t[pos] == ' ') ++pos;
        const bool minus = pos < t.size() && t[pos] == '-';
        if (pos >= t.size() || (t[pos] != '+' && t[pos] != '-')) fail(l, pos + 1, "'+' expected");
        ++pos;
        const double d = number(l, t, pos);
        zoff_ += minus ? -d : d;
      } else {
        zoff_ = number(l, t, pos);
      }
      end_of_statement(l, pos, false);
      return;
    }
    if (starts(t, "$BASE")) {
      pos = 5;
      expect(l, t, pos, '=');
      while (pos < t.size() && t[pos] == ' ') ++pos;
      if (t.compare(pos, 10, "BASE_DATA[") != 0) fail(l, pos + 1, "BASE_DATA[n] expected");
      pos += 10;
      number(l, t, pos);
      expect(l, t, pos, ']');
      while (pos < t.size() && t[pos] == ' ') ++pos;
      base_shift_ = 0;
      if (pos < t.size() && t[pos] == ':') {
        ++pos;
        while (pos < t.size() && t[pos] == ' ') ++pos;
        if (t.compare(pos, 8, "NCB_ZOFF") != 0) fail(l, pos + 1, "NCB_ZOFF expected");
        pos += 8;
        base_shift_ = zoff_;
      }
      end_of_statement(l, pos, false);
      return;
    }
    if (starts(t, "$TOOL") || starts(t, "$APO.CDIS") || starts(t, "BAS(")) return;
    fail(l, 1, "a KRL statement ncbridge does not read");
  }

  void finish_motion(Motion& m) {
    m.feed = feed_;
    const double length = path_length(m);
    m.extrusion = rate_ * length;
    position_ = m.end;
    emit(std::move(m));
  }

  void circ(const Line& l, const Vec3& aux, const Vec3& end, double ca) {
    // The plane: the one of the three principal planes all three points lie in.
    const Vec3& s = position_;
    canonical::Plane plane;
    auto same = [](double a, double b, double c) { return std::abs(a - b) < 1e-6 && std::abs(a - c) < 1e-6; };
    if (same(s.z, aux.z, end.z)) plane = canonical::Plane::XY;
    else if (same(s.y, aux.y, end.y)) plane = canonical::Plane::XZ;
    else if (same(s.x, aux.x, end.x)) plane = canonical::Plane::YZ;
    else fail(l, 1, "a CIRC outside the XY, XZ and YZ planes is not read");
    const PlanePoint a = to_plane(s, plane), b = to_plane(aux, plane), c = to_plane(end, plane);
    const double bu = b.first - a.first, bv = b.second - a.second, cu = c.first - a.first, cv = c.second - a.second;
    const double d = 2 * (bu * cv - bv * cu);
    if (std::abs(d) < 1e-12) fail(l, 1, "the CIRC's three points are on a line");
    const double b2 = bu * bu + bv * bv, c2 = cu * cu + cv * cv;
    Motion m;
    m.kind = MotionKind::Arc;
    m.start = s;
    m.end = ca != 0 ? s : end;
    m.arc.plane = plane;
    m.arc.first_centre = a.first + (cv * b2 - bv * c2) / d;
    m.arc.second_centre = a.second + (bu * c2 - cu * b2) / d;
    m.arc.ccw = (ca < 0) != (d > 0);  // start -> aux -> end turns counter-clockwise when d > 0
    finish_motion(m);
  }

  std::uint64_t for_count(const Line& l) {
    // FOR NCB_LAYER = 1 TO n
    const std::string& t = l.upper;
    std::size_t pos = 4;
    while (pos < t.size() && t[pos] == ' ') ++pos;
    std::size_t name_end = pos;
    while (name_end < t.size() && (std::isalnum(static_cast<unsigned char>(t[name_end])) || t[name_end] == '_')) ++name_end;
    if (name_end == pos) fail(l, pos + 1, "a loop variable expected");
    pos = name_end;
    expect(l, t, pos, '=');
    const double first = number(l, t, pos);
    while (pos < t.size() && t[pos] == ' ') ++pos;
    if (t.compare(pos, 2, "TO") != 0) fail(l, pos + 1, "TO expected");
    pos += 2;
    const double last = number(l, t, pos);
    end_of_statement(l, pos, false);
    if (first != std::floor(first) || last != std::floor(last)) fail(l, 1, "FOR bounds must be integers");
    return last >= first ? static_cast<std::uint64_t>(last - first + 1) : 0;
  }

  std::string name_;
  ElementSink& sink_;
  Vec3 position_{};
  bool known_ = false;
  double feed_ = 0;
  double rate_ = 0;
  double zoff_ = 0;
  double base_shift_ = 0;
  std::uint64_t iterations_ = 0;
  bool counted_ = true;
};

}  // namespace

KrlCounts read_krl_text(std::string_view src, const std::string& name, ElementSink& sink) {
  // Statements of the main DEF, upper case, comments gone; the local NCB_FILAMENT subprogram and
  // the & header lines are skipped.
  std::vector<Line> lines;
  std::uint32_t number = 0;
  enum class Part { Before, Main, After, Local } part = Part::Before;
  std::size_t begin = 0;
  KrlCounts counts;
  auto fail = [&](std::uint32_t line, std::uint32_t column, const std::string& message) {
    throw InputError({name, line, column}, message);
  };
  while (begin < src.size()) {
    std::size_t end = src.find('\n', begin);
    if (end == std::string_view::npos) end = src.size();
    std::string_view raw = src.substr(begin, end - begin);
    begin = end + 1;
    ++number;
    ++counts.lines;
    for (std::size_t i = 0; i < raw.size(); ++i) {
      const auto c = static_cast<unsigned char>(raw[i]);
      if (c == 0 || (c < 0x20 && c != '\t' && c != '\r')) fail(number, static_cast<std::uint32_t>(i + 1), "binary data in a KRL line");
    }
    std::string_view code = raw.substr(0, raw.find(';'));
    std::size_t lead = 0;
    while (lead < code.size() && (code[lead] == ' ' || code[lead] == '\t')) ++lead;
    while (!code.empty() && (code.back() == ' ' || code.back() == '\t' || code.back() == '\r')) code.remove_suffix(1);
    if (lead >= code.size()) continue;
    std::string upper;
    for (std::size_t i = lead; i < code.size(); ++i) {
      const char c = code[i] == '\t' ? ' ' : code[i];
      upper.push_back(static_cast<char>(std::toupper(static_cast<unsigned char>(c))));
    }
    if (upper[0] == '&') continue;
    if (upper.compare(0, 4, "DEF ") == 0) {
      if (part == Part::Before) part = Part::Main;
      else if (part == Part::After) part = Part::Local;
      else fail(number, 1, "DEF inside a DEF");
      continue;
    }
    if (upper == "END") {
      if (part == Part::Main) part = Part::After;
      else if (part == Part::Local) part = Part::After;
      else fail(number, 1, "END without DEF");
      continue;
    }
    if (part == Part::Local) continue;
    if (part != Part::Main) fail(number, static_cast<std::uint32_t>(lead + 1), "a statement outside DEF ... END");
    lines.push_back({upper, number, static_cast<std::uint32_t>(lead + 1)});
  }
  if (part == Part::Main) fail(number, 0, "DEF without END");
  if (part == Part::Before) fail(number, 0, "no DEF in the file");
  Reader reader(name, sink);
  reader.run(lines, 0, lines.size());
  sink.end();
  counts.motion_statements = reader.counts.motion_statements;
  counts.loops = reader.counts.loops;
  return counts;
}

}  // namespace ncbridge::toolpath_optimizer
