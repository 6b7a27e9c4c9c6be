#include "same_motion.hpp"

#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <numbers>
#include <optional>
#include <set>
#include <sstream>
#include <vector>

#include "support/canon_listing.hpp"

namespace ncbridge::testing {

namespace {

struct Value {
  std::vector<std::string> words;  // a call's name (for on/off states) or its arguments
  std::vector<double> mm;          // lengths converted to mm, when the state holds lengths
  double tolerance = 0;
};

struct Action {
  std::string name;
  std::vector<std::string> args;
  std::vector<std::pair<std::string, Value>> state;
  std::string text;
};

const std::map<std::string, std::string, std::less<>> kStateKey = {
    {"USE_LENGTH_UNITS", "units"}, {"SET_G5X_OFFSET", "g5x"}, {"SET_G92_OFFSET", "g92"}, {"SET_XY_ROTATION", "rotation"},
    {"SELECT_PLANE", "plane"}, {"SET_TRAVERSE_RATE", "traverse"}, {"SET_FEED_RATE", "feed"},
    {"SET_FEED_REFERENCE", "feed_reference"}, {"SET_FEED_MODE", "feed_mode"}, {"SET_MOTION_CONTROL_MODE", "control"},
    {"SET_NAIVECAM_TOLERANCE", "naive"}, {"SET_SPINDLE_SPEED", "speed"}, {"SET_SPINDLE_MODE", "spindle_mode"},
    {"USE_TOOL_LENGTH_OFFSET", "tool_length"}, {"SELECT_TOOL", "tool"}, {"START_SPINDLE_CLOCKWISE", "spindle"},
    {"START_SPINDLE_COUNTERCLOCKWISE", "spindle"}, {"STOP_SPINDLE_TURNING", "spindle"}, {"FLOOD_ON", "flood"},
    {"FLOOD_OFF", "flood"}, {"MIST_ON", "mist"}, {"MIST_OFF", "mist"}, {"ENABLE_FEED_OVERRIDE", "feed_override"},
    {"DISABLE_FEED_OVERRIDE", "feed_override"}, {"ENABLE_SPEED_OVERRIDE", "speed_override"},
    {"DISABLE_SPEED_OVERRIDE", "speed_override"}, {"ENABLE_ADAPTIVE_FEED", "adaptive_feed"},
    {"DISABLE_ADAPTIVE_FEED", "adaptive_feed"}, {"ENABLE_FEED_HOLD", "feed_hold"}, {"DISABLE_FEED_HOLD", "feed_hold"},
    {"START_SPEED_FEED_SYNCH", "synch"}, {"STOP_SPEED_FEED_SYNCH", "synch"}};

// States set by which call it is (on/off), not by arguments.
const std::set<std::string, std::less<>> kSwitch = {"spindle", "flood", "mist", "feed_override", "speed_override",
                                                    "adaptive_feed", "feed_hold"};

const std::vector<std::string> kFrame = {"units", "g5x", "g92", "rotation", "tool_length"};
const std::vector<std::string> kActuators = {"spindle", "speed", "spindle_mode", "flood", "mist"};
const std::vector<std::string> kPath = {"control", "naive"};
const std::vector<std::string> kFeed = {"feed", "feed_mode", "feed_reference", "feed_override", "speed_override",
                                        "adaptive_feed", "feed_hold", "synch"};

bool number(const std::string& s, double& v) {
  if (s.empty()) return false;
  char* end = nullptr;
  v = std::strtod(s.c_str(), &end);
  return end == s.c_str() + s.size();
}

std::map<std::string, Value> initial_state() {
  auto words = [](std::vector<std::string> w) { return Value{std::move(w), {}, 0}; };
  auto mm = [](std::vector<double> v) { return Value{{}, std::move(v), 1e-4}; };
  return {{"units", words({"CANON_UNITS_MM"})},
          {"g5x", mm({1, 0, 0, 0, 0, 0, 0})},
          {"g92", mm({0, 0, 0, 0, 0, 0})},
          {"rotation", words({"0.0000"})},
          {"plane", words({"CANON_PLANE_XY"})},
          {"feed", mm({0})},
          {"feed_mode", words({"0", "0"})},
          {"feed_reference", words({"CANON_XYZ"})},
          {"control", words({"CANON_CONTINUOUS", "0.000000"})},
          {"naive", words({"0.0000"})},
          {"speed", words({"0", "0.0000"})},
          {"spindle_mode", words({"0", "0.0000"})},
          {"tool_length", mm({0, 0, 0, 0, 0, 0, 0, 0, 0})},
          {"spindle", words({"STOP_SPINDLE_TURNING"})},
          {"flood", words({"FLOOD_OFF"})},
          {"mist", words({"MIST_OFF"})},
          {"feed_override", words({"ENABLE_FEED_OVERRIDE"})},
          {"speed_override", words({"ENABLE_SPEED_OVERRIDE"})},
          {"adaptive_feed", words({"DISABLE_ADAPTIVE_FEED"})},
          {"feed_hold", words({"ENABLE_FEED_HOLD"})},
          {"synch", words({"STOP_SPEED_FEED_SYNCH"})}};
}

bool same_word(const std::string& a, const std::string& b, double tolerance) {
  double x = 0, y = 0;
  if (number(a, x) && number(b, y)) return std::fabs(x - y) <= tolerance * (1 + 1e-6) + 1e-12;
  return a == b;
}

bool same_value(const Value& a, const Value& b, double tolerance) {
  if (a.words.size() != b.words.size() || a.mm.size() != b.mm.size()) return false;
  for (std::size_t i = 0; i < a.words.size(); ++i) {
    if (!same_word(a.words[i], b.words[i], tolerance)) return false;
  }
  const double t = std::max(a.tolerance, b.tolerance) * (1 + 1e-6) + 1e-12;
  for (std::size_t i = 0; i < a.mm.size(); ++i) {
    if (std::fabs(a.mm[i] - b.mm[i]) > t) return false;
  }
  return true;
}

std::string show(const Value& v) {
  std::ostringstream s;
  for (const auto& w : v.words) s << w << ' ';
  for (double d : v.mm) s << d << ' ';
  return s.str();
}

// ARC_FEED(first_end, second_end, first_axis, second_axis, rotation, axis_end, a, b, c)
std::vector<CanonLine> one_turn_arcs(const std::vector<CanonLine>& lines) {
  std::vector<CanonLine> out;
  std::string plane = "XY";
  std::optional<std::array<double, 3>> position;  // x y z
  for (const CanonLine& line : lines) {
    if (line.name == "SELECT_PLANE" && !line.args.empty()) plane = line.args[0].substr(line.args[0].size() - 2);
    if ((line.name == "STRAIGHT_TRAVERSE" || line.name == "STRAIGHT_FEED") && line.args.size() >= 3) {
      position = std::array<double, 3>{std::atof(line.args[0].c_str()), std::atof(line.args[1].c_str()),
                                       std::atof(line.args[2].c_str())};
    }
    if (line.name != "ARC_FEED" || line.args.size() < 6) {
      out.push_back(line);
      continue;
    }
    double v[6];
    for (int i = 0; i < 6; ++i) v[i] = std::atof(line.args[static_cast<std::size_t>(i)].c_str());
    const int rotation = static_cast<int>(v[4]);
    // plane axes as indices into x y z: first, second, normal
    const int first = plane == "XZ" ? 2 : plane == "YZ" ? 1 : 0;
    const int second = plane == "XZ" ? 0 : plane == "YZ" ? 2 : 1;
    const int normal = plane == "XZ" ? 1 : plane == "YZ" ? 0 : 2;
    CanonLine last = line;
    if ((rotation > 1 || rotation < -1) && position) {
      const double s1 = (*position)[static_cast<std::size_t>(first)], s2 = (*position)[static_cast<std::size_t>(second)];
      const double sn = (*position)[static_cast<std::size_t>(normal)];
      const double two_pi = 2 * std::numbers::pi;
      const double a0 = std::atan2(s2 - v[3], s1 - v[2]), a1 = std::atan2(v[1] - v[3], v[0] - v[2]);
      double base = rotation > 0 ? a1 - a0 : a0 - a1;
      while (base <= 1e-12) base += two_pi;
      while (base > two_pi + 1e-12) base -= two_pi;
      const int turns = rotation < 0 ? -rotation : rotation;
      const double total = base + two_pi * (turns - 1);
      for (int k = 1; k < turns; ++k) {
        CanonLine piece = line;
        char buffer[64];
        std::snprintf(buffer, sizeof buffer, "%.4f", s1);
        piece.args[0] = buffer;
        std::snprintf(buffer, sizeof buffer, "%.4f", s2);
        piece.args[1] = buffer;
        piece.args[4] = rotation < 0 ? "-1" : "1";
        std::snprintf(buffer, sizeof buffer, "%.4f", sn + (v[5] - sn) * (two_pi * k / total));
        piece.args[5] = buffer;
        piece.text += "  [one turn of it]";
        out.push_back(piece);
      }
      last.args[4] = rotation < 0 ? "-1" : "1";
    }
    out.push_back(last);
    std::array<double, 3> end{};
    end[static_cast<std::size_t>(first)] = v[0];
    end[static_cast<std::size_t>(second)] = v[1];
    end[static_cast<std::size_t>(normal)] = v[5];
    position = end;
  }
  return out;
}

std::vector<Action> actions_of(std::string_view listing) {
  std::vector<Action> actions;
  std::map<std::string, Value> state = initial_state();
  std::optional<std::vector<double>> position = std::vector<double>(6, 0.0);  // readers start at 0
  for (const CanonLine& line : one_turn_arcs(parse_canon_listing(listing))) {
    const std::string& name = line.name;
    if (name == "COMMENT" || name == "MESSAGE" || name == "ON_RESET" || name == "FINISH") continue;
    if (name.empty()) {
      actions.push_back({"(not a call)", {}, {}, line.text});
      continue;
    }
    if (auto key = kStateKey.find(name); key != kStateKey.end()) {
      Value v;
      const bool inch = state["units"].words[0] == "CANON_UNITS_INCHES";
      const double k = inch ? 25.4 : 1.0;
      if (kSwitch.count(key->second)) {
        v.words = {name};
      } else if (key->second == "feed" || key->second == "tool_length" || key->second == "g5x" ||
                 key->second == "g92") {
        // lengths (a, b, c in degrees where the call has them: g5x 4..6, g92 3..5, tool_length 3..5)
        for (std::size_t i = 0; i < line.args.size(); ++i) {
          double d = 0;
          number(line.args[i], d);
          const bool angle = (key->second == "g5x" && i >= 4 && i <= 6) || (key->second != "g5x" && key->second != "feed" && i >= 3 && i <= 5);
          const bool index = key->second == "g5x" && i == 0;
          v.mm.push_back(angle || index ? d : d * k);
        }
        v.tolerance = 1e-4 * k;
      } else {
        v.words = line.args;
      }
      if (!same_value(state[key->second], v, 1e-9)) {
        // the program position moves when the frame does (the machine stays where it is)
        if (position && key->second == "units") {
          const double f = v.words[0] == "CANON_UNITS_INCHES" ? 1 / 25.4 : 25.4;
          if (v.words[0] != state["units"].words[0]) {
            for (std::size_t i = 0; i < position->size(); ++i) {
              if (i < 3) (*position)[i] *= f;
            }
          }
        } else if (position && (key->second == "tool_length" || key->second == "g5x" || key->second == "g92")) {
          // (SET_G5X_OFFSET names the active system's offset, after its index)
          const std::size_t first = key->second == "g5x" ? 1 : 0;
          const Value& old = state[key->second];
          for (std::size_t i = 0; i < 6 && i < position->size(); ++i) {
            const std::size_t j = first + i;
            if (j >= old.mm.size() || j >= v.mm.size()) break;
            (*position)[i] += (old.mm[j] - v.mm[j]) / (i < 3 ? k : 1.0);
          }
        } else if (key->second == "units" || key->second == "g5x" || key->second == "g92" || key->second == "tool_length") {
          position.reset();
        }
        state[key->second] = v;
      }
      continue;
    }
    const bool straight = name == "STRAIGHT_TRAVERSE" || name == "STRAIGHT_FEED";
    if (straight) {
      std::vector<double> end;
      for (const auto& a : line.args) end.push_back(std::atof(a.c_str()));
      bool still = position && position->size() == end.size();
      // (within half the listing's last digit: a shorter move prints as no move)
      for (std::size_t i = 0; still && i < end.size(); ++i) still = std::fabs((*position)[i] - end[i]) < 5e-5;
      position = end;
      if (still) continue;
    } else if (name == "ARC_FEED") {
      position.reset();
    }
    std::vector<std::string> keys;
    const bool move = straight || name == "ARC_FEED" || name == "STRAIGHT_PROBE" || name == "RIGID_TAP";
    if (move) {
      keys = kFrame;
      keys.insert(keys.end(), kActuators.begin(), kActuators.end());
      if (name != "STRAIGHT_TRAVERSE") {
        keys.push_back("control");
        if (state["control"].words[0] == "CANON_CONTINUOUS") keys.push_back("naive");
      }
      keys.push_back("tool");
      if (name != "STRAIGHT_TRAVERSE") keys.insert(keys.end(), kFeed.begin(), kFeed.end());
      if (name == "ARC_FEED") keys.push_back("plane");
    } else if (name == "DWELL" || name == "PROGRAM_STOP" || name == "OPTIONAL_PROGRAM_STOP") {
      keys = kActuators;
    }
    Action a{name, line.args, {}, line.text};
    for (const auto& k : keys) a.state.emplace_back(k, state[k]);
    actions.push_back(std::move(a));
  }
  return actions;
}

}  // namespace

MotionComparison compare_motion(std::string_view expected_listing, std::string_view actual_listing, double tolerance) {
  MotionComparison result;
  const std::vector<Action> e = actions_of(expected_listing);
  const std::vector<Action> a = actions_of(actual_listing);
  const std::size_t n = std::min(e.size(), a.size());
  for (std::size_t i = 0; i < n; ++i, ++result.actions) {
    std::string why;
    if (e[i].name != a[i].name || e[i].args.size() != a[i].args.size()) {
      why = "a different action";
    } else {
      for (std::size_t k = 0; k < e[i].args.size() && why.empty(); ++k) {
        if (!same_word(e[i].args[k], a[i].args[k], tolerance)) why = "argument " + std::to_string(k + 1) + " differs";
      }
      for (std::size_t k = 0; k < e[i].state.size() && why.empty(); ++k) {
        if (!same_value(e[i].state[k].second, a[i].state[k].second, tolerance)) {
          why = "the state " + e[i].state[k].first + " differs: " + show(e[i].state[k].second) + "vs " +
                show(a[i].state[k].second);
        }
      }
    }
    if (!why.empty()) {
      result.equal = false;
      result.report = "action " + std::to_string(i + 1) + ": " + why + "\n  expected: " + e[i].text +
                      "\n  actual:   " + a[i].text;
      return result;
    }
  }
  if (e.size() != a.size()) {
    result.equal = false;
    const auto& longer = e.size() > a.size() ? e : a;
    result.report = "expected " + std::to_string(e.size()) + " actions, got " + std::to_string(a.size()) +
                    "; first extra: " + longer[n].text;
  }
  return result;
}

}  // namespace ncbridge::testing
