#include "setup_checks.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <variant>

namespace ncbridge::cli {

namespace {

constexpr std::size_t kReportsPerKind = 10;  // warnings of one kind printed; the rest are counted
constexpr double kPi = 3.14159265358979323846;

std::string number(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", v);
  return text;
}

std::string_view body_name(stepnc::ToolBody body) {
  using B = stepnc::ToolBody;
  switch (body) {
    case B::Facemill: return "face mill";
    case B::Endmill: return "end mill";
    case B::BallEndmill: return "ball end mill";
    case B::BullnoseEndmill: return "bull nose end mill";
    case B::TSlotMill: return "T-slot mill";
    case B::TwistDrill: return "drill";
    case B::Centerdrill: return "centre drill";
    case B::Countersink: return "countersink";
    case B::Reamer: return "reamer";
    case B::Tap: return "tap";
    case B::BoringTool: return "boring tool";
    case B::UserDefinedTool: return "tool";
  }
  return "tool";
}

// Cut along the axis (per revolution) rather than with the side (per tooth).
bool makes_holes(stepnc::ToolBody body) {
  using B = stepnc::ToolBody;
  return body == B::TwistDrill || body == B::Centerdrill || body == B::Reamer || body == B::BoringTool;
}

std::string describe(const stepnc::MillingCuttingTool& tool) {
  std::string text = tool.its_id + " (" + std::string(body_name(tool.body)) + " D" + number(tool.dimension.diameter);
  if (tool.number_of_teeth) text += ", " + std::to_string(*tool.number_of_teeth) + " teeth";
  return text + ")";
}

stepnc::CartesianPoint add(const stepnc::CartesianPoint& a, const stepnc::Direction& d, double s) {
  return {a.x + d.x * s, a.y + d.y * s, a.z + d.z * s};
}

// The points of a toolpath curve: polyline vertices, and arcs sampled every 10 degrees.
template <typename Visit>
void for_each_point(const stepnc::CompositeCurve& curve, Visit&& visit) {
  for (const stepnc::CurveSegment& segment : curve.segments) {
    if (const auto* line = std::get_if<stepnc::Polyline>(&segment)) {
      for (const auto& p : line->points) visit(p);
      continue;
    }
    const auto& arc = std::get<stepnc::TrimmedCircle>(segment);
    const auto& axis = arc.position.axis;
    const auto& ref = arc.position.ref_direction;
    const stepnc::Direction side{axis.y * ref.z - axis.z * ref.y, axis.z * ref.x - axis.x * ref.z,
                                 axis.x * ref.y - axis.y * ref.x};
    const double sweep = stepnc::sweep_degrees(arc) * (arc.sense_agreement ? 1 : -1);
    const int steps = std::max(1, static_cast<int>(std::ceil(std::abs(sweep) / 10)));
    for (int i = 0; i <= steps; ++i) {
      const double t = (arc.trim_1_parameter + sweep * i / steps) * kPi / 180;
      visit(add(add(arc.position.location, ref, arc.radius * std::cos(t)), side, arc.radius * std::sin(t)));
    }
    visit(arc.trim_2_point);
  }
}

// Built member by member: brace-initialised, GCC 12 warns of an uninitialised string.
Warning make_warning(std::string kind, SourceLocation where, std::string message) {
  Warning w;
  w.kind = std::move(kind);
  w.where = std::move(where);
  w.message = std::move(message);
  return w;
}

SourceLocation in_file(const std::string& file) {
  SourceLocation at;
  at.file = file;
  return at;
}

}  // namespace

// ---- ProgramFacts ----

void ProgramFacts::source_file(std::uint32_t index, std::string_view path) {
  if (files_.size() <= index) files_.resize(index + 1);
  files_[index] = std::string(path);
}

void ProgramFacts::call(const canonical::Call& c) {
  if (const auto* units = std::get_if<canonical::UseLengthUnits>(&c.data)) {
    units_ = units->units;
    units_where_ = where({c.source.file, c.source.line, c.source.line});
  } else if (!cutting_units_ &&
             (std::holds_alternative<canonical::StraightFeed>(c.data) || std::holds_alternative<canonical::ArcFeed>(c.data))) {
    cutting_units_ = units_;
    units_set_at_ = units_where_;
  }
}

SourceLocation ProgramFacts::where(const stepnc::SourceLines& lines) const {
  SourceLocation at;
  if (lines.file < files_.size()) at.file = files_[lines.file];
  at.line = lines.first_line;
  return at;
}

// ---- SetupChecks ----

SetupChecks::SetupChecks(SetupCheckInputs inputs, const ProgramFacts* facts)
    : inputs_(std::move(inputs)), facts_(facts), stock_(inputs_.stock) {}

SourceLocation SetupChecks::where(const stepnc::SourceLines& lines) const {
  SourceLocation at = facts_ ? facts_->where(lines) : SourceLocation{};
  if (at.file.empty()) at.file = inputs_.program;
  if (!facts_) at.line = 0;  // a CC1 file: the lines are not its own
  return at;
}

void SetupChecks::element(const stepnc::Project& project, const stepnc::Executable& element) {
  if (!stock_ && project.rawpiece && project.rawpiece->its_bounding_geometry) {  // a CC1 file's own stock
    const stepnc::Block& b = *project.rawpiece->its_bounding_geometry;
    setup::Stock s;
    s.min = {b.position.location.x, b.position.location.y, b.position.location.z};
    s.max = {s.min[0] + b.x, s.min[1] + b.y, s.min[2] + b.z};
    stock_ = s;
  }
  const auto* ws = std::get_if<stepnc::MachiningWorkingstep>(&element);
  if (!ws) return;
  check_feed(project, *ws);
  check_inside_stock(project, *ws);
}

// A feed is plausible when the chip it makes is: for mills the feed per tooth fz = F / (S z),
// for drills, reamers and boring tools the feed per revolution f = F / S, against bounds that
// grow with the diameter D (mm). Without a spindle speed only absurd feeds are flagged.
void SetupChecks::check_feed(const stepnc::Project& project, const stepnc::MachiningWorkingstep& ws) {
  const auto& mop = stepnc::machining_operation(project.operation(ws.its_operation));
  if (!feeds_checked_.insert({mop.its_tool.index, mop.its_technology.index}).second) return;
  const auto& tool = project.tool(mop.its_tool);
  const auto& technology = project.technology(mop.its_technology);
  const double diameter = tool.dimension.diameter;
  if (!technology.feedrate || *technology.feedrate <= 0 || diameter <= 0) return;
  if (tool.body == stepnc::ToolBody::Tap) return;  // a tap's feed is its pitch, synchronised
  const double feed = *technology.feedrate * 60000;  // mm/min
  const double rpm = technology.spindle ? std::abs(*technology.spindle) * 60 : 0;
  const std::string head = "feed " + number(feed) + " mm/min";
  const std::string hint = inputs_.heidenhain_per_minute
                               ? " Was the program posted in mm/s (FreeCAD's Heidenhain post)? Then give --heidenhain-feed-units mm/s."
                               : " Check the program's feed units and the tool list.";
  if (rpm <= 0) {
    if (feed < 1 || feed > 100000) {
      report("feed", where(ws.source),
             head + " for " + describe(tool) + " is implausible for any cutting (1 to 100000 mm/min)." + hint);
    }
    return;
  }
  const double per_rev = feed / rpm;
  const bool holes = makes_holes(tool.body);
  const double teeth = tool.number_of_teeth && *tool.number_of_teeth > 0 ? static_cast<double>(*tool.number_of_teeth) : 0;
  // Unknown teeth: the most lenient count for each bound (1 for too slow, 8 for too fast).
  const double slow = holes ? per_rev : per_rev / (teeth > 0 ? teeth : 1);
  const double fast = holes ? per_rev : per_rev / (teeth > 0 ? teeth : 8);
  const double low = holes ? 0.002 * diameter + 0.001 : 0.0002 * diameter + 0.001;
  const double high = holes ? 0.1 * diameter + 0.1 : 0.05 * diameter + 0.25;
  const std::string per = holes ? " mm per revolution" : " mm per tooth";
  const std::string at = head + " at " + number(rpm) + " rpm with " + describe(tool) + " is ";
  if (slow < low) {
    std::string message = at + number(slow) + per + ", implausibly slow (" + number(low) + " at least).";
    if (slow * 60 >= low && slow * 60 <= high) message += " 60 times that would be plausible.";
    report("feed", where(ws.source), message + hint);
  } else if (fast > high) {
    std::string message = at + number(fast) + per + ", implausibly fast (" + number(high) + " at most).";
    if (fast / 60 >= low && fast / 60 <= high) message += " A 60th of it would be plausible.";
    report("feed", where(ws.source), message + hint);
  }
}

// Cutting below the stock top, the tool centre may pass the stock's sides by two tool diameters
// and 5 mm (overhang, lead-in and -out), its bottom by half a diameter and 2 mm (drill points
// through the part).
void SetupChecks::check_inside_stock(const stepnc::Project& project, const stepnc::MachiningWorkingstep& ws) {
  const setup::Stock* s = stock();
  if (!s) return;
  const auto& mop = stepnc::machining_operation(project.operation(ws.its_operation));
  const auto* hole = std::get_if<stepnc::RoundHole>(&project.feature(ws.its_feature));
  if (!mop.its_toolpath && !hole) return;
  const double diameter = project.tool(mop.its_tool).dimension.diameter;
  const double side_margin = 2 * diameter + 5, bottom_margin = diameter / 2 + 2;
  double worst = 0;
  std::string side;
  stepnc::CartesianPoint worst_point;
  double limit = 0;
  const auto visit = [&](const stepnc::CartesianPoint& p) {
    if (p.z >= s->max[2]) return;  // above the stock: air
    const std::array<std::pair<double, const char*>, 5> beyond{{
        {s->min[0] - side_margin - p.x, "x-"}, {p.x - s->max[0] - side_margin, "x+"},
        {s->min[1] - side_margin - p.y, "y-"}, {p.y - s->max[1] - side_margin, "y+"},
        {s->min[2] - bottom_margin - p.z, "bottom"}}};
    for (const auto& [amount, name] : beyond) {
      if (amount > worst) {
        worst = amount;
        side = name;
        worst_point = p;
      }
    }
  };
  if (mop.its_toolpath) {
    for (const auto& trajectory : mop.its_toolpath->its_list) for_each_point(trajectory.basiccurve, visit);
  } else {  // a drilling cycle: the hole, from its placement down to its depth plane
    const stepnc::CartesianPoint top = hole->feature_placement.location;
    visit(top);
    visit(add(top, hole->feature_placement.axis, hole->depth.position.location.z));
  }
  if (worst <= 0) return;
  if (side == "bottom") {
    limit = s->min[2];
  } else {
    const int axis = side[0] == 'x' ? 0 : 1;
    limit = side[1] == '-' ? s->min[axis] : s->max[axis];
  }
  const double past = side == "bottom" ? limit - worst_point.z : std::abs((side[0] == 'x' ? worst_point.x : worst_point.y) - limit);
  std::string message = ws.its_id + " cuts " + number(past) + " mm ";
  message += side == "bottom" ? "below the stock's bottom (Z" + number(limit) + ")"
                              : "beyond the stock's " + side + " side (" + std::string(1, static_cast<char>(std::toupper(side[0]))) +
                                    number(limit) + ")";
  message += " at X" + number(worst_point.x) + " Y" + number(worst_point.y) + " Z" + number(worst_point.z) + " with a D" +
             number(diameter) + " tool: is the stock right (size, position, units)?";
  report("outside_stock", where(ws.source), message);
}

void SetupChecks::report(const std::string& kind, SourceLocation at, std::string message) {
  auto& [reported, more] = per_kind_[kind];
  if (reported == kReportsPerKind) {
    ++more;
    return;
  }
  ++reported;
  warnings_.push_back(make_warning(kind, std::move(at), std::move(message)));
}

void SetupChecks::finish(const stepnc::Project& project) {
  for (const auto& [kind, counts] : per_kind_) {
    if (counts.second > 0) {
      warnings_.push_back(make_warning(kind, in_file(inputs_.program),
                                       "and " + std::to_string(counts.second) + " more " + kind + " warnings"));
    }
  }
  if (const setup::Stock* s = stock()) {
    const double z = project.setup.its_secplane.position.location.z;
    const std::string plane = inputs_.security_plane ? "the security plane (--security-plane " + number(z) + ")"
                                                     : "the security plane Z" + number(z) + " (the program's highest rapid)";
    const std::string stock = " (Z" + number(s->min[2]) + " to Z" + number(s->max[2]) + ")";
    if (z < s->min[2]) {
      warnings_.push_back(make_warning("security_plane", in_file(inputs_.program),
                                       plane + " is below the stock" + stock + ": is the stock's Z right?"));
    } else if (z < s->max[2]) {
      warnings_.push_back(make_warning("security_plane", in_file(inputs_.program),
                                       plane + " is inside the stock" + stock +
                                           ": moves between workingsteps would cut; is the stock's Z right?"));
    }
  }
  if (facts_ && facts_->cutting_units() && inputs_.stock) {
    const bool program_inch = *facts_->cutting_units() == canonical::Units::Inches;
    const bool stock_inch = inputs_.stock->file_units == setup::LengthUnits::Inches;
    if (program_inch != stock_inch) {
      SourceLocation at = facts_->units_set_at();
      if (at.file.empty()) at.file = inputs_.program;
      warnings_.push_back(make_warning("units", at,
                           std::string("the program cuts in ") + (program_inch ? "inches (G20)" : "mm (G21)") + " but the stock " +
                               inputs_.stock_file + " is in " + (stock_inch ? "inches" : "mm") +
                               (stock_inch ? "" : (" (no \"units\" means mm)")) + ": if its numbers are " +
                               (program_inch ? "inches, add \"units\": \"inch\"" : "mm, set \"units\": \"mm\"")));
    }
  }
  if (inputs_.tools) {
    for (const auto& used : project.tools) {
      const setup::Tool* tool = inputs_.tools->find(used.number);
      if (tool && tool->type == setup::ToolType::Unknown) {
        warnings_.push_back(make_warning("tool_type", in_file(inputs_.tools_file),
                             "tool " + std::to_string(used.number) + (tool->name.empty() ? "" : " (" + tool->name + ")") +
                                 " has no \"type\": it is written as a user-defined tool, and the feed check and feature "
                                 "recognition cannot tell a drill from a mill"));
      }
    }
  }
}

}  // namespace ncbridge::cli
