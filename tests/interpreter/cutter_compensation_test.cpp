// Cutter radius compensation against LinuxCNC's rs274: each program in comp_cases/ is played
// into CutterCompensation by a small driver that knows just the words those programs use, and
// the calls that come out are compared with what rs274 printed for the same program
// (comp_cases/NAME.canon, NAME.error; regenerate.sh re-runs rs274).
#include "cutter_compensation.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <variant>
#include <vector>

namespace ncbridge::interpreter {
namespace {

namespace fs = std::filesystem;
using canonical::ArcFeed;
using canonical::Call;
using canonical::Pose;
using canonical::Side;
using canonical::Source;
using canonical::Units;

const fs::path kCases = fs::path(NCBRIDGE_SOURCE_DIR) / "tests/interpreter/comp_cases";

struct Recorder : canonical::Sink {
  std::vector<Call> calls;
  void call(const Call& c) override { calls.push_back(c); }
};

// One canonical call as rs274 prints it: name, numbers, or one text argument.
struct Printed {
  std::string name;
  std::vector<double> numbers;
  std::string text;
};

std::string to_string(const Printed& p) {
  std::ostringstream out;
  out << p.name << '(';
  if (!p.text.empty()) out << '"' << p.text << '"';
  for (std::size_t i = 0; i < p.numbers.size(); ++i) out << (i ? ", " : "") << p.numbers[i];
  out << ')';
  return out.str();
}

Printed printed(const Call& call) {
  Printed p{std::string(canonical::name_of(call.data)), {}, {}};
  std::visit(
      [&p](const auto& d) {
        using T = std::decay_t<decltype(d)>;
        if constexpr (std::is_same_v<T, canonical::StraightFeed> || std::is_same_v<T, canonical::StraightTraverse>) {
          p.numbers = {d.end.x, d.end.y, d.end.z, d.end.a, d.end.b, d.end.c};
        } else if constexpr (std::is_same_v<T, ArcFeed>) {
          p.numbers = {d.first_end, d.second_end, d.first_axis, d.second_axis, double(d.rotation),
                       d.axis_end_point, d.a, d.b, d.c};
        } else if constexpr (std::is_same_v<T, canonical::SetFeedRate>) {
          p.numbers = {d.rate};
        } else if constexpr (std::is_same_v<T, canonical::Dwell>) {
          p.numbers = {d.seconds};
        } else if constexpr (std::is_same_v<T, canonical::SetSpindleSpeed>) {
          p.numbers = {double(d.spindle), d.rpm};
        } else if constexpr (std::is_same_v<T, canonical::StartSpindleClockwise> ||
                             std::is_same_v<T, canonical::StartSpindleCounterclockwise> ||
                             std::is_same_v<T, canonical::StopSpindleTurning>) {
          p.numbers = {double(d.spindle)};
        } else if constexpr (std::is_same_v<T, canonical::SetFeedMode>) {
          p.numbers = {double(d.spindle), double(d.mode)};
        } else if constexpr (std::is_same_v<T, canonical::OrientSpindle>) {
          p.numbers = {double(d.spindle), d.orientation, double(d.mode)};
        } else if constexpr (std::is_same_v<T, canonical::SelectTool>) {
          p.numbers = {double(d.tool)};
        } else if constexpr (std::is_same_v<T, canonical::Comment> || std::is_same_v<T, canonical::Message>) {
          p.text = d.text;
        } else if constexpr (std::is_same_v<T, canonical::UseLengthUnits>) {
          p.text = d.units == Units::Inches ? "CANON_UNITS_INCHES" : "CANON_UNITS_MM";
        } else if constexpr (std::is_same_v<T, canonical::SelectPlane>) {
          p.text = "CANON_PLANE_XY";
        }
      },
      call.data);
  return p;
}

// "   12 N..... STRAIGHT_FEED(0.9500, 0.0500, ...)" -> Printed; nullopt for other lines.
std::optional<Printed> parse_rs274_line(const std::string& line) {
  const auto open = line.find('(');
  const auto n = line.find(" N");
  if (open == std::string::npos || n == std::string::npos || line.back() != ')') return std::nullopt;
  const auto name_start = line.find(' ', n + 1) + 1;
  Printed p{line.substr(name_start, open - name_start), {}, {}};
  std::string args = line.substr(open + 1, line.size() - open - 2);
  if (!args.empty() && args.front() == '"') {
    p.text = args.substr(1, args.size() - 2);
  } else if (args.find("CANON_") != std::string::npos) {
    p.text = args;
  } else {
    std::replace(args.begin(), args.end(), ',', ' ');
    std::istringstream in(args);
    for (double v; in >> v;) p.numbers.push_back(v);
  }
  return p;
}

struct Expected {
  std::vector<Printed> calls;  // from the program's first block to its M2 (or the error)
  std::string error;           // rs274's message, empty when the program ran to the end
  std::string error_block;     // the block rs274 names with the error
};

std::vector<std::string> read_lines(const fs::path& file) {
  std::ifstream in(file);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

Expected read_expected(const std::string& name) {
  Expected e;
  bool after_startup = false;
  for (const std::string& line : read_lines(kCases / (name + ".canon"))) {
    auto p = parse_rs274_line(line);
    if (!p) continue;
    if (!after_startup) {  // rs274's own start-up calls end with the first ON_RESET
      after_startup = p->name == "ON_RESET";
      continue;
    }
    if (p->name == "SET_G5X_OFFSET" || p->name == "ON_RESET") break;  // M2's reset, or the stop
    e.calls.push_back(*p);
  }
  if (fs::exists(kCases / (name + ".error"))) {
    auto lines = read_lines(kCases / (name + ".error"));
    if (!lines.empty()) e.error = lines[0];
    if (lines.size() > 1) e.error_block = lines[1];
  }
  return e;
}

// LinuxCNC tool table: diameters in inches by tool number.
std::map<int, double> read_diameters() {
  std::map<int, double> diameters;
  for (const std::string& line : read_lines(kCases / "tools.tbl")) {
    std::istringstream in(line.substr(0, line.find(';')));
    int tool = -1;
    double diameter = 0;
    for (std::string word; in >> word;) {
      if (word[0] == 'T') tool = std::stoi(word.substr(1));
      if (word[0] == 'D') diameter = std::stod(word.substr(1));
    }
    if (tool >= 0) diameters[tool] = diameter;
  }
  return diameters;
}

struct Outcome {
  std::vector<Call> calls;
  std::optional<InputError> error;
};

// Plays a case program: one block per line, words in LinuxCNC's order of execution, only the
// words the cases use (comments, F S T M0 M2 M3 M4 M5 M8 M9 M19 G0-G4 G17 G20 G21 G40-G42 G90
// G91 G94 G95, X Y Z I J R P D). Compensation gets programmed geometry; the driver keeps the programmed point.
Outcome play(const std::string& name) {
  const auto diameters = read_diameters();
  Recorder recorder;
  CutterCompensation comp(
      recorder,
      [&name](const Source& s) { return SourceLocation{name + ".ngc", s.line, 1}; },
      Units::Millimeters);
  Outcome outcome;
  Pose position;
  Units units = Units::Millimeters;
  bool incremental = false;
  int motion = -1;
  std::uint32_t line_number = 0;
  try {
    for (const std::string& raw : read_lines(kCases / (name + ".ngc"))) {
      const Source source{0, ++line_number, -1};
      std::string line = raw;
      std::optional<std::string> comment;
      if (auto open = line.find('('); open != std::string::npos) {
        comment = line.substr(open + 1, line.find(')') - open - 1);
        line.erase(open);
      }
      std::multimap<char, double> words;
      for (std::size_t i = 0; i < line.size();) {
        char letter = char(std::toupper(static_cast<unsigned char>(line[i])));
        if (!std::isalpha(static_cast<unsigned char>(letter))) { ++i; continue; }
        std::size_t used = 0;
        double value = std::stod(line.substr(i + 1), &used);
        words.emplace(letter, value);
        i += 1 + used;
      }
      auto has = [&](char letter, double value) {
        auto [b, e] = words.equal_range(letter);
        return std::any_of(b, e, [value](const auto& w) { return std::fabs(w.second - value) < 1e-9; });
      };
      auto word = [&](char letter) -> std::optional<double> {
        auto it = words.find(letter);
        return it == words.end() ? std::nullopt : std::optional<double>(it->second);
      };
      auto other = [&](canonical::Data data) { comp.other(Call{std::move(data), source, std::nullopt}); };

      if (comment) {
        if (comment->rfind("MSG,", 0) == 0) other(canonical::Message{comment->substr(4)});
        else other(canonical::Comment{*comment});
      }
      for (int g : {94, 95}) {
        if (!has('G', g)) continue;
        other(canonical::Comment{g == 94 ? "interpreter: feed mode set to units per minute"
                                         : "interpreter: feed mode set to units per revolution"});
        other(canonical::SetFeedMode{0, g == 94 ? 0 : 1});
        other(canonical::SetFeedRate{0});
      }
      if (auto f = word('F')) other(canonical::SetFeedRate{*f});
      if (auto s = word('S')) other(canonical::SetSpindleSpeed{0, *s});
      if (auto t = word('T')) other(canonical::SelectTool{int(*t)});
      if (has('M', 3)) other(canonical::StartSpindleClockwise{0});
      if (has('M', 4)) other(canonical::StartSpindleCounterclockwise{0});
      if (has('M', 5)) other(canonical::StopSpindleTurning{0});
      if (has('M', 19)) other(canonical::OrientSpindle{0, word('R').value_or(0.0), 0});
      if (has('M', 8)) other(canonical::FloodOn{});
      if (has('M', 9)) { other(canonical::MistOff{}); other(canonical::FloodOff{}); }
      if (has('G', 4)) other(canonical::Dwell{*word('P')});
      if (has('G', 17)) other(canonical::SelectPlane{canonical::Plane::XY});
      for (Units u : {Units::Inches, Units::Millimeters}) {
        if (!has('G', u == Units::Inches ? 20 : 21)) continue;
        if (u != units) {
          const double factor = u == Units::Millimeters ? 25.4 : 1 / 25.4;
          position.x *= factor; position.y *= factor; position.z *= factor;
          units = u;
        }
        other(canonical::UseLengthUnits{u});
      }
      if (has('G', 40)) {
        const bool was_active = comp.active();
        comp.stop(source);
        if (was_active) position = comp.programmed_position();
      }
      for (Side side : {Side::Left, Side::Right}) {
        if (!has('G', side == Side::Left ? 41 : 42)) continue;
        const double diameter = diameters.at(int(*word('D')));
        comp.set_position(position);
        comp.start(side, diameter * (units == Units::Millimeters ? 25.4 : 1.0) / 2, source);
      }
      if (has('G', 90) && incremental) { incremental = false; other(canonical::Comment{"interpreter: distance mode changed to absolute"}); }
      if (has('G', 91) && !incremental) { incremental = true; other(canonical::Comment{"interpreter: distance mode changed to incremental"}); }
      for (int g : {0, 1, 2, 3}) if (has('G', g)) motion = g;
      if (word('X') || word('Y') || word('Z')) {
        Pose end = position;
        if (auto x = word('X')) end.x = incremental ? end.x + *x : *x;
        if (auto y = word('Y')) end.y = incremental ? end.y + *y : *y;
        if (auto z = word('Z')) end.z = incremental ? end.z + *z : *z;
        if (motion == 0 || motion == 1) {
          comp.straight(motion == 1, end, source);
        } else {
          double cx = position.x + word('I').value_or(0.0);
          double cy = position.y + word('J').value_or(0.0);
          if (auto r = word('R')) {  // centre on the chord's bisector; R < 0: the long way round
            const double mx = (position.x + end.x) / 2;
            const double my = (position.y + end.y) / 2;
            const double half = std::hypot(end.x - mx, end.y - my);
            const bool right_of_chord = (motion == 2) == (*r > 0);
            const double dir = std::atan2(end.y - position.y, end.x - position.x) +
                               (right_of_chord ? -M_PI_2 : M_PI_2);
            const double offset = std::fabs(*r) * std::cos(std::asin(std::min(1.0, half / std::fabs(*r))));
            cx = mx + offset * std::cos(dir);
            cy = my + offset * std::sin(dir);
          }
          comp.arc(ArcFeed{end.x, end.y, cx, cy, motion == 3 ? 1 : -1, end.z, 0, 0, 0, 0, 0, 0}, source);
        }
        position = end;
      }
      if (has('M', 0)) {
        comp.flush();
        other(canonical::ProgramStop{});
      }
      if (has('M', 2)) {
        comp.flush();
        comp.reset();
        break;
      }
    }
  } catch (const InputError& error) {
    outcome.error = error;
  }
  outcome.calls = recorder.calls;
  return outcome;
}

std::string listing(const std::vector<Printed>& calls) {
  std::string out;
  for (const auto& c : calls) out += "  " + to_string(c) + "\n";
  return out;
}

class Rs274Case : public testing::TestWithParam<std::string> {};

TEST_P(Rs274Case, EmitsWhatRs274Emits) {
  const std::string name = GetParam();
  const Expected expected = read_expected(name);
  const Outcome outcome = play(name);

  std::vector<Printed> actual;
  for (const Call& c : outcome.calls) actual.push_back(printed(c));
  const std::string both = "rs274:\n" + listing(expected.calls) + "ours:\n" + listing(actual);
  ASSERT_EQ(actual.size(), expected.calls.size()) << both;
  for (std::size_t i = 0; i < actual.size(); ++i) {
    const Printed& want = expected.calls[i];
    const Printed& got = actual[i];
    ASSERT_EQ(got.name, want.name) << "call " << i << "\n" << both;
    ASSERT_EQ(got.text, want.text) << "call " << i << "\n" << both;
    ASSERT_EQ(got.numbers.size(), want.numbers.size()) << "call " << i << "\n" << both;
    for (std::size_t k = 0; k < got.numbers.size(); ++k) {
      // rs274 prints %.4f: agree to the printed digit.
      EXPECT_NEAR(got.numbers[k], want.numbers[k], 0.51e-4) << "call " << i << " argument " << k << "\n" << both;
    }
  }

  if (expected.error.empty()) {
    EXPECT_FALSE(outcome.error) << outcome.error->what();
    return;
  }
  ASSERT_TRUE(outcome.error) << "rs274 stopped with: " << expected.error;
  EXPECT_EQ(outcome.error->message(), expected.error);
  EXPECT_EQ(outcome.error->where().file, name + ".ngc");
  const auto lines = read_lines(kCases / (name + ".ngc"));
  ASSERT_GE(outcome.error->where().line, 1u);
  ASSERT_LE(outcome.error->where().line, lines.size());
  EXPECT_EQ(lines[outcome.error->where().line - 1], expected.error_block);
}

std::vector<std::string> case_names() {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(kCases))
    if (entry.path().extension() == ".ngc") names.push_back(entry.path().stem().string());
  std::sort(names.begin(), names.end());
  return names;
}

INSTANTIATE_TEST_SUITE_P(CompCases, Rs274Case, testing::ValuesIn(case_names()),
                         [](const testing::TestParamInfo<std::string>& case_info) { return case_info.param; });

TEST(CompCases, CoverEnoughPrograms) {
  EXPECT_GE(case_names().size(), 15u);
}

// ---- Behaviour the rs274 cases do not pin down

Pose at(double x, double y, double z = 0) { return Pose{x, y, z, 0, 0, 0, 0, 0, 0}; }

void expect_xy(const Pose& pose, double x, double y) {
  EXPECT_NEAR(pose.x, x, 1e-12);
  EXPECT_NEAR(pose.y, y, 1e-12);
}

TEST(CutterCompensation, WithoutCompensationMovesPassStraightThrough) {
  Recorder r;
  CutterCompensation comp(r);
  comp.straight(true, at(1, 2, 3), {0, 1, -1});
  comp.arc(ArcFeed{2, 2, 1.5, 2, 1, 3, 0, 0, 0, 0, 0, 0}, {0, 2, -1});
  ASSERT_EQ(r.calls.size(), 2u);
  EXPECT_EQ(std::get<canonical::StraightFeed>(r.calls[0].data).end, at(1, 2, 3));
  EXPECT_EQ(std::get<ArcFeed>(r.calls[1].data).first_end, 2);
  EXPECT_EQ(comp.position(), at(2, 2, 3));
}

TEST(CutterCompensation, NothingLeavesBeforeTheNextMoveDecidesTheCorner) {
  Recorder r;
  CutterCompensation comp(r);
  comp.set_position(at(0, 0));
  comp.start(Side::Left, 1.0);
  ASSERT_EQ(r.calls.size(), 1u);  // the "on" comment
  comp.straight(true, at(10, 0), {0, 3, -1});
  comp.other(Call{canonical::FloodOn{}, {0, 4, -1}, std::nullopt});
  EXPECT_EQ(r.calls.size(), 1u);
  comp.straight(true, at(10, 10), {0, 5, -1});  // concave corner: the first line is trimmed
  ASSERT_EQ(r.calls.size(), 3u);
  expect_xy(std::get<canonical::StraightFeed>(r.calls[1].data).end, 9, 1);
  EXPECT_EQ(r.calls[1].source.line, 3u);
  EXPECT_TRUE(std::holds_alternative<canonical::FloodOn>(r.calls[2].data));
  comp.flush();
  ASSERT_EQ(r.calls.size(), 4u);
  expect_xy(std::get<canonical::StraightFeed>(r.calls[3].data).end, 9, 10);
  expect_xy(comp.position(), 9, 10);
  EXPECT_EQ(comp.programmed_position(), at(10, 10));
}

TEST(CutterCompensation, ErrorsCarryTheLocationOfTheBlock) {
  Recorder r;
  CutterCompensation comp(r, [](const Source& s) { return SourceLocation{"part.ngc", s.line, 7}; });
  comp.set_position(at(0, 0));
  comp.start(Side::Right, 2.0);
  try {
    comp.straight(true, at(1, 0), {0, 42, -1});
    FAIL() << "an entry move shorter than the radius must be refused";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().file, "part.ngc");
    EXPECT_EQ(e.where().line, 42u);
    EXPECT_EQ(e.where().column, 7u);
    EXPECT_EQ(e.message(), "Length of cutter compensation entry move is not greater than the tool radius");
  }
}

TEST(CutterCompensation, DegenerateMovesNeitherHangNorProduceNonFiniteCoordinates) {
  // A fixed pseudo-random walk over a coarse grid: repeated points, reversals, collinear
  // runs, full circles, arcs tangent to lines, radius 0. Every emitted number must be finite;
  // refusals must be InputErrors.
  std::uint64_t state = 0x9e3779b97f4a7c15ull;
  auto next = [&state](int n) {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    return int((state >> 33) % std::uint64_t(n));
  };
  int refused = 0;
  int emitted = 0;
  for (int run = 0; run < 300; ++run) {
    Recorder r;
    CutterCompensation comp(r);
    Pose p = at(next(5), next(5));
    comp.set_position(p);
    comp.start(next(2) ? Side::Left : Side::Right, next(4) * 0.25);
    try {
      for (int step = 0; step < 12; ++step) {
        Pose end = next(4) ? at(next(5), next(5), next(2)) : p;
        const int kind = next(3);
        if (kind < 2) {
          comp.straight(kind == 1, end, {0, std::uint32_t(step + 1), -1});
        } else {
          // centre on the perpendicular bisector (or the start itself for a full circle)
          const double cx = (p.x + end.x) / 2 - (end.y - p.y) * (next(3) - 1);
          const double cy = (p.y + end.y) / 2 + (end.x - p.x) * (next(3) - 1);
          const bool full = end.x == p.x && end.y == p.y;
          comp.arc(ArcFeed{end.x, end.y, full ? p.x + 1 : cx, full ? p.y : cy, next(2) ? 1 : -1, end.z,
                           0, 0, 0, 0, 0, 0},
                   {0, std::uint32_t(step + 1), -1});
        }
        p = end;
      }
      comp.stop();
    } catch (const InputError&) {
      ++refused;
    }
    for (const Call& c : r.calls)
      for (double v : printed(c).numbers) {
        ASSERT_TRUE(std::isfinite(v)) << "run " << run << ": " << to_string(printed(c));
        ++emitted;
      }
  }
  EXPECT_GT(emitted, 0);
  EXPECT_GT(refused, 0);
}

TEST(CutterCompensation, ResetDropsThePendingMoveLikeAnEndOfFileWithoutM2) {
  // rs274 on "G41 D1 / G1 X1 F10 / G1 X1 Y1 / %" prints the first line only: the last
  // compensated move is still waiting for its corner when the file ends.
  Recorder r;
  CutterCompensation comp(r);
  comp.set_position(at(0, 0));
  comp.start(Side::Left, 0.05);
  comp.straight(true, at(1, 0), {0, 4, -1});
  comp.straight(true, at(1, 1), {0, 5, -1});
  comp.reset();
  EXPECT_FALSE(comp.active());
  ASSERT_EQ(r.calls.size(), 2u);  // the comment and the first line
  expect_xy(std::get<canonical::StraightFeed>(r.calls[1].data).end, 0.95, 0.05);
  comp.flush();
  EXPECT_EQ(r.calls.size(), 2u);
}

TEST(CutterCompensation, StartWhileOnIsRefused) {
  Recorder r;
  CutterCompensation comp(r);
  comp.start(Side::Left, 1.0, {0, 3, -1});
  EXPECT_THROW(comp.start(Side::Right, 1.0, {0, 4, -1}), InputError);
  comp.stop();
  EXPECT_FALSE(comp.active());
  EXPECT_NO_THROW(comp.start(Side::Right, 1.0, {0, 5, -1}));
}

}  // namespace
}  // namespace ncbridge::interpreter
