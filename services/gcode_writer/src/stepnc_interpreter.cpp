// CC1 project -> canonical calls (stepnc_interpreter.hpp).
#include "ncbridge/gcode_writer/stepnc_interpreter.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <type_traits>

#include "cycle_motion.hpp"
#include "machine_state.hpp"
#include "ncbridge/common/error.hpp"

namespace ncbridge::gcode_writer {

using namespace canonical;
namespace sn = stepnc;

namespace {

constexpr double kMmPerMinutePerMetrePerSecond = 60000.0;
constexpr double kSamePoint = 1e-6;  // mm

// A placement as a frame: its location, ref_direction (x), axis x ref_direction (y), axis (z).
struct Frame {
  sn::CartesianPoint origin{0, 0, 0};
  sn::Direction x{1, 0, 0}, y{0, 1, 0}, z{0, 0, 1};

  static sn::Direction unit(const sn::Direction& d) {
    const double n = std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
    return n > 0 ? sn::Direction{d.x / n, d.y / n, d.z / n} : d;
  }
  static Frame of(const sn::Axis2Placement3d& a) {
    Frame f;
    f.origin = a.location;
    f.z = unit(a.axis);
    // ref_direction projected normal to the axis
    const sn::Direction r = unit(a.ref_direction);
    const double d = r.x * f.z.x + r.y * f.z.y + r.z * f.z.z;
    f.x = unit({r.x - d * f.z.x, r.y - d * f.z.y, r.z - d * f.z.z});
    f.y = {f.z.y * f.x.z - f.z.z * f.x.y, f.z.z * f.x.x - f.z.x * f.x.z, f.z.x * f.x.y - f.z.y * f.x.x};
    return f;
  }
  sn::CartesianPoint point(const sn::CartesianPoint& p) const {
    return {origin.x + p.x * x.x + p.y * y.x + p.z * z.x, origin.y + p.x * x.y + p.y * y.y + p.z * z.y,
            origin.z + p.x * x.z + p.y * y.z + p.z * z.z};
  }
  sn::Direction direction(const sn::Direction& d) const {
    return {d.x * x.x + d.y * y.x + d.z * z.x, d.x * x.y + d.y * y.y + d.z * z.y, d.x * x.z + d.y * y.z + d.z * z.z};
  }
};

Pose pose(const sn::CartesianPoint& p) {
  Pose r;
  r.x = p.x;
  r.y = p.y;
  r.z = p.z;
  return r;
}

double distance(const Pose& a, const Pose& b) { return std::sqrt((a.x - b.x) * (a.x - b.x) + (a.y - b.y) * (a.y - b.y) + (a.z - b.z) * (a.z - b.z)); }

const sn::Axis2Placement3d* feature_placement(const sn::Feature& f) {
  return std::visit(
      [](const auto& feature) -> const sn::Axis2Placement3d* {
        if constexpr (std::is_same_v<std::decay_t<decltype(feature)>, sn::Region>) {
          return feature.feature_placement ? &*feature.feature_placement : nullptr;
        } else {
          return &feature.feature_placement;
        }
      },
      f);
}

std::string id_of(const sn::Feature& f) {
  return std::visit([](const auto& feature) { return feature.its_id; }, f);
}

class Interpreter {
 public:
  Interpreter(const sn::Project& project, const std::string& file, const StepncOptions& options, Sink& sink)
      : project_(project), file_(file), options_(options), sink_(sink) {
    const setup::ToolList tools = stepnc_tools(project);
    for (std::size_t i = 0; i < project.tools.size(); ++i) {
      // stepnc_tools numbers the project's tools in the same order
      numbers_.push_back(tools_number(project, i));
    }
  }

  void run() {
    sink_.source_file(0, file_);
    emit(UseLengthUnits{Units::Millimeters});
    emit(SetG5xOffset{1, Pose{}});
    emit(SetG92Offset{Pose{}});
    emit(SetXyRotation{0});
    emit(SetFeedReference{FeedReference::Xyz});
    emit(OnReset{});
    const auto& elements = project_.main_workplan.its_elements;
    for (std::size_t i = 0; i < elements.size(); ++i) {
      source_.line = static_cast<std::uint32_t>(i + 1);
      std::visit([&](const auto& e) { element(e, i); }, elements[i]);
    }
    source_.line = 0;
    emit(PalletShuttle{});
    emit(ProgramEnd{});
    sink_.end();
  }

 private:
  static int tools_number(const sn::Project& project, std::size_t index) {
    int highest = 0;
    for (const auto& t : project.tools) highest = std::max(highest, t.number);
    int next = highest;
    for (std::size_t i = 0; i < project.tools.size(); ++i) {
      const int n = project.tools[i].number > 0 ? project.tools[i].number : ++next;
      if (i == index) return n;
    }
    return 0;
  }

  [[noreturn]] void fail(const std::string& message) const {
    throw InputError({file_, source_.line, 0}, "workplan element " + std::to_string(source_.line) + " '" + element_id_ +
                                                   "': " + message);
  }

  void emit(Data d) {
    state_.apply(d);
    sink_.call(Call{std::move(d), source_, tag_});
  }

  void name(const std::string& what, const std::string& id) {
    element_id_ = id;
    if (options_.name_workingsteps) emit(Comment{what + " " + id});
  }

  // ---- resources
  void use_tool(sn::ToolRef ref, bool change_anyway = false) {
    if (ref.index >= project_.tools.size()) fail("its tool is not in the project's tools");
    const int number = numbers_[ref.index];
    if (tool_loaded_ && number == state_.tool_in_spindle && !change_anyway) return;
    emit(SelectTool{number});
    emit(StartChange{});
    emit(StopSpindleTurning{0});
    emit(ChangeTool{number});
    Pose length;
    length.z = project_.tools[ref.index].tool_offset_length;
    emit(UseToolLengthOffset{length});
    tool_loaded_ = true;
    position_known_ = false;  // the tool change moved the spindle
  }

  void use_functions(const sn::MillingTechnology& t, const sn::MillingMachineFunctions& f) {
    if (t.spindle) {
      const double rpm = std::fabs(*t.spindle) * 60.0;
      if (rpm != state_.speed && rpm > 0) emit(SetSpindleSpeed{0, rpm});
      const Direction d = *t.spindle < 0 ? Direction::Clockwise : *t.spindle > 0 ? Direction::Counterclockwise : Direction::Stopped;
      if (d != state_.spindle) {
        if (d == Direction::Clockwise) emit(StartSpindleClockwise{0});
        else if (d == Direction::Counterclockwise) emit(StartSpindleCounterclockwise{0});
        else emit(StopSpindleTurning{0});
      }
    }
    const bool mist = f.mist.value_or(false);
    if (f.coolant != state_.flood) f.coolant ? emit(FloodOn{}) : emit(FloodOff{});
    if (mist != state_.mist) mist ? emit(MistOn{}) : emit(MistOff{});
  }

  void use_feed(const sn::MillingTechnology& t) {
    if (!t.feedrate) return;
    const double f = *t.feedrate * kMmPerMinutePerMetrePerSecond;
    if (t.synchronize_spindle_with_feed) fail("a feed per revolution (synchronize_spindle_with_feed)");
    if (std::fabs(f - state_.feed_mm) > 1e-9) emit(SetFeedRate{f});
  }

  const sn::MillingTechnology& technology(sn::TechnologyRef r) const {
    if (r.index >= project_.technologies.size()) fail("its technology is not in the project");
    return project_.technologies[r.index];
  }
  const sn::MillingMachineFunctions& functions(sn::MachineFunctionsRef r) const {
    if (r.index >= project_.machine_functions.size()) fail("its machine functions are not in the project");
    return project_.machine_functions[r.index];
  }

  // ---- moves
  void traverse(const Pose& to) {
    emit(StraightTraverse{to});
    position_known_ = true;
  }
  void feed(const Pose& to) {
    if (state_.feed_mm <= 0) fail("a feed move with no feed rate (MILLING_TECHNOLOGY.feedrate)");
    emit(StraightFeed{to});
    position_known_ = true;
  }

  // To the start of a path: straight from an unknown position (after a tool change, as the
  // program did), else up to the security plane, across and down.
  void go_to(const Pose& start, double security_z, bool rapid_path) {
    if (!position_known_) {
      // a rapid movement is the way in; a cut is entered from above it at the security plane
      // when it starts below that
      if (!rapid_path && start.z < security_z - kSamePoint) {
        Pose above = start;
        above.z = security_z;
        traverse(above);
      }
      traverse(start);
      return;
    }
    const Pose& here = state_.position;
    if (distance(here, start) <= kSamePoint) return;
    if (options_.name_workingsteps) emit(Comment{"ncbridge: connecting move over the security plane"});
    const double high = std::max({security_z, here.z, start.z});
    Pose p = here;
    if (p.z < high) {
      p.z = high;
      traverse(p);
    }
    p.x = start.x;
    p.y = start.y;
    if (distance(p, state_.position) > kSamePoint) traverse(p);
    if (distance(start, state_.position) > kSamePoint) traverse(start);
  }

  void curve(const sn::CompositeCurve& c, const Frame& frame, bool rapid, double security_z) {
    for (const sn::CurveSegment& segment : c.segments) {
      if (const auto* line = std::get_if<sn::Polyline>(&segment)) {
        if (line->points.empty()) fail("a polyline without points");
        go_to(pose(frame.point(line->points.front())), security_z, rapid);
        for (std::size_t k = 1; k < line->points.size(); ++k) {
          const Pose to = pose(frame.point(line->points[k]));
          if (rapid) traverse(to); else feed(to);
        }
      } else {
        arc(std::get<sn::TrimmedCircle>(segment), frame, rapid, security_z);
      }
    }
  }

  void arc(const sn::TrimmedCircle& a, const Frame& frame, bool rapid, double security_z) {
    if (rapid) fail("an arc in a rapid toolpath");
    const Frame circle = Frame::of(a.position);
    const sn::CartesianPoint centre = frame.point(a.position.location);
    const sn::Direction axis = frame.direction(circle.z);
    const Pose start = pose(frame.point(a.trim_1_point));
    const Pose end = pose(frame.point(a.trim_2_point));
    go_to(start, security_z, false);
    Plane plane;
    double positive;
    if (std::fabs(axis.z) > 1 - 1e-9) {
      plane = Plane::XY;
      positive = axis.z;
    } else if (std::fabs(axis.x) > 1 - 1e-9) {
      plane = Plane::YZ;
      positive = axis.x;
    } else if (std::fabs(axis.y) > 1 - 1e-9) {
      plane = Plane::XZ;
      positive = axis.y;
    } else {
      fail("an arc in a plane not parallel to XY, YZ or XZ");
    }
    if (plane != state_.plane) emit(SelectPlane{plane});
    const bool ccw = a.sense_agreement == (positive > 0);
    ArcFeed f{};
    f.rotation = ccw ? 1 : -1;
    switch (plane) {
      case Plane::YZ:
        f.first_end = end.y; f.second_end = end.z; f.first_axis = centre.y; f.second_axis = centre.z; f.axis_end_point = end.x;
        break;
      case Plane::XZ:
        f.first_end = end.z; f.second_end = end.x; f.first_axis = centre.z; f.second_axis = centre.x; f.axis_end_point = end.y;
        break;
      default:
        f.first_end = end.x; f.second_end = end.y; f.first_axis = centre.x; f.second_axis = centre.y; f.axis_end_point = end.z;
        break;
    }
    if (state_.feed_mm <= 0) fail("an arc with no feed rate (MILLING_TECHNOLOGY.feedrate)");
    emit(f);
  }

  // ---- elements
  void element(const sn::RapidMovement& r, std::size_t index) {
    name("rapid movement", r.its_id);
    // Two rapid movements in a row were split by a tool change (docs/cc1.md): the first moves
    // the tool in the spindle away from its cut, the second brings the next cut's tool to it.
    const auto& elements = project_.main_workplan.its_elements;
    const bool split = index + 1 < elements.size() && std::holds_alternative<sn::RapidMovement>(elements[index + 1]);
    if (!split) prepare_for_next_workingstep(index, false);
    if (r.its_toolpath) {
      const double security_z = r.its_secplane.position.location.z;
      for (const auto& t : r.its_toolpath->its_list) curve(t.basiccurve, Frame{}, true, security_z);
    }
    if (split) prepare_for_next_workingstep(index, true);
  }

  // A WORKPIECE_PROBING (docs/cc1.md): the probe moves from its start along its direction until
  // it touches, expected within expected_value of the start; as G38.2 to the end of the range
  // (theoretical size + upper limit), at the feed in effect.
  void element(const sn::WorkpieceProbing& w, std::size_t) {
    name("workpiece probing", w.its_id);
    const double reach = w.expected_value.theoretical_size + w.expected_value.upper_limit;
    const sn::Direction& d = w.its_direction;
    const double length = std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
    if (!(reach > 0) || !(length > 0)) fail("a workpiece probing with no travel (expected_value and its_direction)");
    if (state_.feed_mm <= 0) fail("a workpiece probing with no feed rate before it");
    const sn::CartesianPoint& s = w.start_position.location;
    go_to(pose(Frame{}.point(s)), w.its_secplane.position.location.z, true);
    const sn::CartesianPoint end{s.x + d.x / length * reach, s.y + d.y / length * reach, s.z + d.z / length * reach};
    emit(StraightProbe{pose(Frame{}.point(end)), 0});
    position_known_ = true;  // as the CC1 builder reads a probe move: the path goes on from its end
  }

  // The tool, spindle and coolant of the cut an approach leads to are there before it (the
  // program changed the tool and started the spindle before it moved up to the cut); between
  // two rapid movements only the tool changes.
  void prepare_for_next_workingstep(std::size_t index, bool change_anyway) {
    const auto& elements = project_.main_workplan.its_elements;
    for (std::size_t j = index + 1; j < elements.size(); ++j) {
      const auto* ws = std::get_if<sn::MachiningWorkingstep>(&elements[j]);
      if (ws == nullptr) continue;
      if (ws->its_operation.index >= project_.operations.size()) return;
      const sn::MachiningOperation& op = sn::machining_operation(project_.operations[ws->its_operation.index]);
      use_tool(op.its_tool, change_anyway);
      if (!change_anyway) use_functions(technology(op.its_technology), functions(op.its_machine_functions));
      return;
    }
  }

  void element(const sn::MachiningWorkingstep& ws, std::size_t index) {
    name("workingstep", ws.its_id);
    if (ws.its_operation.index >= project_.operations.size()) fail("its operation is not in the project");
    const sn::Operation& operation = project_.operations[ws.its_operation.index];
    const sn::MachiningOperation& op = sn::machining_operation(operation);
    if (ws.its_feature.index >= project_.features.size()) fail("its feature is not in the project");
    const sn::Feature& feature = project_.features[ws.its_feature.index];
    use_tool(op.its_tool);
    const sn::MillingTechnology& tech = technology(op.its_technology);
    use_functions(tech, functions(op.its_machine_functions));
    use_feed(tech);
    const double security_z = ws.its_secplane.position.location.z;
    if (op.its_toolpath) {
      Frame frame;
      if (options_.toolpath_frame == StepncOptions::ToolpathFrame::Feature) {
        if (const auto* placement = feature_placement(feature)) frame = Frame::of(*placement);
      }
      for (const auto& t : op.its_toolpath->its_list) {
        const sn::MillingTechnology& tt = t.its_technology ? technology(*t.its_technology) : tech;
        const sn::MillingMachineFunctions& tf =
            t.its_machine_functions ? functions(*t.its_machine_functions) : functions(op.its_machine_functions);
        use_functions(tt, tf);
        use_feed(tt);
        const bool rapid = t.its_type == sn::ToolpathType::Connect || t.its_type == sn::ToolpathType::NonContact;
        curve(t.basiccurve, frame, rapid, security_z);
      }
      return;
    }
    std::visit(
        [&](const auto& o) {
          using T = std::decay_t<decltype(o)>;
          if constexpr (std::is_base_of_v<sn::DrillingTypeOperation, T>) {
            const auto* hole = std::get_if<sn::RoundHole>(&feature);
            if (hole == nullptr) fail("a drilling operation on " + id_of(feature) + ", which is not a ROUND_HOLE");
            drill(*hole, o, tech, security_z, index);
          } else {
            fail(std::string(sn::entity_name(operation)) +
                 " without an explicit toolpath: a CC2 operation (its toolpath is the toolpath generator's to make)");
          }
        },
        operation);
  }

  // The first point of the rapid movement right after element `index`, if there is one.
  std::optional<Pose> next_rapid_start(std::size_t index) const {
    const auto& elements = project_.main_workplan.its_elements;
    if (index + 1 >= elements.size()) return std::nullopt;
    const auto* r = std::get_if<sn::RapidMovement>(&elements[index + 1]);
    if (r == nullptr || !r->its_toolpath || r->its_toolpath->its_list.empty()) return std::nullopt;
    const auto& segments = r->its_toolpath->its_list.front().basiccurve.segments;
    if (segments.empty()) return std::nullopt;
    const auto* line = std::get_if<sn::Polyline>(&segments.front());
    if (line == nullptr || line->points.empty()) return std::nullopt;
    return pose(line->points.front());
  }

  template <class Op>
  void drill(const sn::RoundHole& hole, const Op& op, const sn::MillingTechnology& tech, double security_z,
             std::size_t index) {
    const Frame f = Frame::of(hole.feature_placement);
    Plane plane;
    double sign;
    if (std::fabs(f.z.z) > 1 - 1e-9) {
      plane = Plane::XY;
      sign = f.z.z;
    } else if (std::fabs(f.z.x) > 1 - 1e-9) {
      plane = Plane::YZ;
      sign = f.z.x;
    } else if (std::fabs(f.z.y) > 1 - 1e-9) {
      plane = Plane::XZ;
      sign = f.z.y;
    } else {
      fail("a hole whose axis is not along X, Y or Z");
    }
    if (sign < 0) fail("a hole drilled upwards along its axis (a back boring)");
    const sn::CartesianPoint& top = hole.feature_placement.location;
    const double depth = op.cutting_depth.value_or(0);
    if (depth <= 0) fail("a drilling operation without cutting_depth");
    const double retract = op.retract_plane.value_or(0);
    const double dwell = op.dwell_time_bottom.value_or(0);
    int g = 810;
    double q = 0;
    if constexpr (std::is_same_v<Op, sn::BackBoring>) {
      fail("BACK_BORING: G87 needs the offsets and levels the model does not keep");
    } else if constexpr (std::is_same_v<Op, sn::MultistepDrilling>) {
      q = op.depth_of_step > 0 ? op.depth_of_step : op.first_depth;
      if (q <= 0) fail("MULTISTEP_DRILLING without a depth of step");
      if (!(depth / q <= 1e5)) fail("MULTISTEP_DRILLING of more than 100000 steps");
      const double rapid_delta = 0.254;  // the executor's G73 retract, mm
      g = op.retract_distance > 0 && op.retract_distance < q - 1e-6 && std::fabs(op.retract_distance - rapid_delta) < 0.05 ? 730 : 830;
    } else if constexpr (std::is_same_v<Op, sn::Tapping>) {
      g = state_.spindle == Direction::Counterclockwise ? 740 : 840;
    } else if constexpr (std::is_same_v<Op, sn::Boring>) {
      if (op.spindle_stop_at_bottom) g = 860;
      else if (op.feed_on_retract.value_or(0) > 0) g = dwell > 0 ? 890 : 850;
      else g = dwell > 0 ? 820 : 810;
    } else if constexpr (std::is_same_v<Op, sn::Reaming>) {
      g = op.feed_on_retract.value_or(0) > 0 ? (dwell > 0 ? 890 : 850) : (dwell > 0 ? 820 : 810);
    } else {
      g = dwell > 0 ? 820 : 810;
    }
    if (op.its_machining_strategy) emit(Comment{"ncbridge: the drilling strategy (reduced feeds) is not applied"});
    use_feed(tech);
    if (state_.feed_mm <= 0) fail("a drilling operation with no feed rate");
    if (plane != state_.plane) emit(SelectPlane{plane});
    // the hole in the plane's axes: first, second, and the normal (along which it is drilled)
    auto coordinates = [&](const sn::CartesianPoint& p, double& a, double& b, double& n) {
      if (plane == Plane::YZ) { a = p.y; b = p.z; n = p.x; }
      else if (plane == Plane::XZ) { a = p.z; b = p.x; n = p.y; }
      else { a = p.x; b = p.y; n = p.z; }
    };
    CycleBlock block;
    double normal = 0;
    coordinates(top, block.a, block.b, normal);
    block.motion = g;
    block.r = normal + retract;
    block.z = normal - depth;
    block.q = q;
    block.p = (g == 820 || g == 860 || g == 890) ? dwell : 0.0;
    if (!position_known_) {
      // straight above the hole at the security plane, then the cycle
      Pose p = state_.position;
      sn::CartesianPoint above = top;
      if (plane == Plane::XY) above.z = std::max(security_z, block.r);
      else if (plane == Plane::YZ) above.x = std::max(security_z, block.r);
      else above.y = std::max(security_z, block.r);
      p.x = above.x;
      p.y = above.y;
      p.z = above.z;
      traverse(p);
    }
    // back to the R plane (G99) when the rapid after the hole starts there, else to the height
    // the tool came from (G98)
    bool to_r = false;
    if (const auto next = next_rapid_start(index)) {
      double a = 0, b = 0, n = 0;
      coordinates(sn::CartesianPoint{next->x, next->y, next->z}, a, b, n);
      to_r = std::fabs(a - block.a) < 1e-6 && std::fabs(b - block.b) < 1e-6 && std::fabs(n - block.r) < 1e-6;
    }
    MachineState s = state_;
    CycleReader reader;
    reader.retract_to_r = to_r;
    std::vector<Data> calls = simulate_cycle(s, reader, block);
    CycleTag tag;
    tag.cycle_id = ++cycle_id_;
    tag.g_code_x10 = static_cast<std::uint16_t>(g);
    tag.retract_to_r = to_r;
    tag.plane = plane == Plane::YZ ? 1 : plane == Plane::XZ ? 2 : 0;
    tag.x = block.a;
    tag.y = block.b;
    tag.clearance = reader.initial_level;
    tag.r = block.r;
    tag.z = block.z;
    tag.q = block.q;
    tag.p = block.p;
    tag_ = tag;
    for (Data& d : calls) emit(std::move(d));
    tag_.reset();
    position_known_ = true;
  }

  const sn::Project& project_;
  std::string file_;
  StepncOptions options_;
  Sink& sink_;
  std::vector<int> numbers_;
  MachineState state_;
  bool tool_loaded_ = false;
  bool position_known_ = false;
  Source source_{0, 0, -1, 0};
  std::optional<CycleTag> tag_;
  std::uint32_t cycle_id_ = 0;
  std::string element_id_;
};

}  // namespace

setup::ToolList stepnc_tools(const sn::Project& project) {
  int highest = 0;
  for (const auto& t : project.tools) highest = std::max(highest, t.number);
  std::vector<setup::Tool> tools;
  for (const auto& t : project.tools) {
    setup::Tool tool;
    tool.number = t.number > 0 ? t.number : ++highest;
    tool.name = t.its_id;
    tool.diameter = t.dimension.diameter;
    tool.length = t.tool_offset_length;
    tools.push_back(tool);
  }
  return setup::ToolList(std::move(tools));
}

void interpret_stepnc(const sn::Project& project, const std::string& file_name, const StepncOptions& options, Sink& sink) {
  Interpreter(project, file_name, options, sink).run();
}

}  // namespace ncbridge::gcode_writer
