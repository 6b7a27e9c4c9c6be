// ISO 14649 model -> Part 21 text. Entity names and attribute orders follow the ISO 14649-10/-11/
// -111 drafts (reference/iso14649/combined_schema_iso14649_only.exp): inherited attributes first,
// `$` only for OPTIONAL attributes, `()` for empty required aggregates.
// Ids are given bottom-up: everything an instance refers to is written before it, PROJECT last,
// so the text streams out as it is made (part21_instance_stream.hpp). One exception: the
// setup's security plane, which every executable names but whose height is known only at the
// end of a streamed program, has an id reserved after the workpiece and is written with the
// SETUP. The workplan is written element by element (StepncStreamWriter), the same way whether
// the elements come from a whole project or one by one from a builder. Shared: each resource
// (tool, technology, machine functions), named placements and planes of equal value, and value
// instances (points, directions, arc placements, circles) repeated while still remembered
// (recent_instances.hpp), such as the point where one toolpath segment ends and the next begins.
#include <algorithm>
#include <array>
#include <functional>
#include <unordered_map>
#include <stdexcept>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

#include "ncbridge/common/version.hpp"
#include "ncbridge/step_writer/part21_reader.hpp"
#include "ncbridge/step_writer/part21_writer.hpp"
#include "ncbridge/step_writer/stepnc_file.hpp"
#include "ncbridge/step_writer/stepnc_stream_writer.hpp"
#include "cc2_writer.hpp"
#include "instance_id_list.hpp"
#include "part21_instance_stream.hpp"
#include "recent_instances.hpp"

namespace ncbridge::step_writer {

namespace {

using part21::InstanceId;
using part21::InstanceStream;
namespace sn = stepnc;

template <class... F> struct Overload : F... { using F::operator()...; };
template <class... F> Overload(F...) -> Overload<F...>;

std::string_view tool_body_entity(sn::ToolBody body) {
  switch (body) {
    case sn::ToolBody::Facemill: return "FACEMILL";
    case sn::ToolBody::Endmill: return "ENDMILL";
    case sn::ToolBody::BallEndmill: return "BALL_ENDMILL";
    case sn::ToolBody::BullnoseEndmill: return "BULLNOSE_ENDMILL";
    case sn::ToolBody::TSlotMill: return "T_SLOT_MILL";
    case sn::ToolBody::TwistDrill: return "TWIST_DRILL";
    case sn::ToolBody::Centerdrill: return "CENTERDRILL";
    case sn::ToolBody::Countersink: return "COUNTERSINK";
    case sn::ToolBody::Reamer: return "REAMER";
    case sn::ToolBody::Tap: return "TAP";
    case sn::ToolBody::BoringTool: return "BORING_TOOL";
    case sn::ToolBody::UserDefinedTool: break;
  }
  return "USER_DEFINED_TOOL";
}

std::string_view toolpath_type_name(sn::ToolpathType t) {
  switch (t) {
    case sn::ToolpathType::Approach: return "APPROACH";
    case sn::ToolpathType::Lift: return "LIFT";
    case sn::ToolpathType::Connect: return "CONNECT";
    case sn::ToolpathType::NonContact: return "NON_CONTACT";
    case sn::ToolpathType::Contact: return "CONTACT";
    case sn::ToolpathType::TrajectoryPath: break;
  }
  return "TRAJECTORY_PATH";
}

std::string_view knot_type_name(sn::KnotType t) {
  switch (t) {
    case sn::KnotType::UniformKnots: return "UNIFORM_KNOTS";
    case sn::KnotType::QuasiUniformKnots: return "QUASI_UNIFORM_KNOTS";
    case sn::KnotType::PiecewiseBezierKnots: return "PIECEWISE_BEZIER_KNOTS";
    case sn::KnotType::Unspecified: break;
  }
  return "UNSPECIFIED";
}

using Bits3 = std::array<std::uint64_t, 3>;
Bits3 bits_of(double x, double y, double z) {
  using R = part21::RecentInstances<3>;
  return {R::bits(x), R::bits(y), R::bits(z)};
}

// A named placement's (or plane's) exact value and name (as an index into the names seen).
using PlacementKey = std::array<std::uint64_t, 10>;
struct PlacementKeyHash {
  std::size_t operator()(const PlacementKey& key) const {
    std::uint64_t h = 0x9E3779B97F4A7C15ull;
    for (std::uint64_t w : key) {
      h ^= w;
      h *= 0xFF51AFD7ED558CCDull;
      h ^= h >> 32;
    }
    return static_cast<std::size_t>(h);
  }
};
PlacementKey key_of(std::uint64_t name, const sn::Axis2Placement3d& a) {
  using R = part21::RecentInstances<3>;
  return {R::bits(a.location.x), R::bits(a.location.y), R::bits(a.location.z), R::bits(a.axis.x), R::bits(a.axis.y),
          R::bits(a.axis.z), R::bits(a.ref_direction.x), R::bits(a.ref_direction.y), R::bits(a.ref_direction.z), name};
}

// Writes a project in three steps: begin() (the workpieces), element() for each executable of
// the workplan in order, finish() (setup, workplan, project). Whole: `p` holds every element,
// features and operations are written once however many workingsteps name them. Streamed: each
// element comes with a project holding the resources so far and the element's own feature and
// operation (a builder's), and only the ids of the executables are kept.
class Cc1Writer {
 public:
  enum class Mode { Whole, Streamed };

  Cc1Writer(InstanceStream& out, Mode mode) : s_(out), streamed_(mode == Mode::Streamed) {}

  void begin(const sn::Project& p) {
    p_ = &p;
    if (!streamed_) index_feature_operations();
    const InstanceId rawpiece = p_->rawpiece ? write_workpiece(*p_->rawpiece, 0) : 0;
    workpiece_ = write_workpiece(p_->workpiece, rawpiece);
    security_plane_ = s_.reserve();
  }

  void element(const sn::Project& p, const sn::Executable& e) {
    p_ = &p;
    executables_.push_back(std::visit([&](const auto& x) { return write_executable(x); }, e));
  }

  void finish(const sn::Project& p) {
    p_ = &p;
    const InstanceId setup = write_setup();
    s_.begin("WORKPLAN");
    s_.string(p_->main_workplan.its_id);
    s_.open_list();
    executables_.for_each([&](InstanceId id) {
      s_.ref(id);
      s_.flush_if_full();
    });
    s_.close_list();
    s_.unset();
    s_.ref(setup);
    s_.unset();
    const InstanceId workplan = s_.end();
    s_.begin("PROJECT");
    s_.string(p_->its_id);
    s_.ref(workplan);
    s_.refs(std::array{workpiece_});
    s_.unset();
    s_.unset();
    s_.unset();
    s_.end();
  }

 private:
  // The written id of a table entry (0: not written yet); tables of a streamed project grow.
  // A reference outside its table (a decoded message can hold any index) throws.
  static InstanceId& written(std::vector<InstanceId>& ids, std::uint32_t index, std::size_t table_size) {
    if (index >= table_size) throw std::out_of_range("write_stepnc: a reference outside its table");
    if (index >= ids.size()) ids.resize(table_size, 0);
    return ids[index];
  }

  // Which operations each feature carries (its_operations), in workplan order, as one flat
  // table: feature f's operations are feature_ops_[feature_first_[f] .. feature_first_[f + 1]).
  void index_feature_operations() {
    feature_first_.assign(p_->features.size() + 1, 0);
    for (const auto& e : p_->main_workplan.its_elements) {
      if (const auto* ws = std::get_if<sn::MachiningWorkingstep>(&e)) ++feature_first_.at(ws->its_feature.index + 1);
    }
    for (std::size_t f = 1; f < feature_first_.size(); ++f) feature_first_[f] += feature_first_[f - 1];
    feature_ops_.resize(feature_first_.back());
    std::vector<std::uint32_t> filled(feature_first_.begin(), feature_first_.end() - 1);
    for (const auto& e : p_->main_workplan.its_elements) {
      if (const auto* ws = std::get_if<sn::MachiningWorkingstep>(&e)) feature_ops_[filled[ws->its_feature.index]++] = ws->its_operation;
    }
  }

  // ---- geometry
  InstanceId point(const sn::CartesianPoint& c) {
    const Bits3 key = bits_of(c.x, c.y, c.z);
    if (const InstanceId id = points_.find(key)) return id;
    s_.begin("CARTESIAN_POINT");
    s_.string("");
    s_.open_list();
    s_.real(c.x);
    s_.real(c.y);
    s_.real(c.z);
    s_.close_list();
    const InstanceId id = s_.end();
    points_.remember(key, id);
    return id;
  }
  InstanceId direction(const sn::Direction& d) {
    const Bits3 key = bits_of(d.x, d.y, d.z);
    if (const InstanceId id = directions_.find(key)) return id;
    s_.begin("DIRECTION");
    s_.string("");
    s_.open_list();
    s_.real(d.x);
    s_.real(d.y);
    s_.real(d.z);
    s_.close_list();
    const InstanceId id = s_.end();
    directions_.remember(key, id);
    return id;
  }
  InstanceId new_placement(const sn::Axis2Placement3d& a, std::string_view name) {
    const InstanceId location = point(a.location);
    const InstanceId axis = direction(a.axis);
    const InstanceId ref_direction = direction(a.ref_direction);
    s_.begin("AXIS2_PLACEMENT_3D");
    s_.string(name);
    s_.ref(location);
    s_.ref(axis);
    s_.ref(ref_direction);
    return s_.end();
  }
  // Named placements and planes (security plane, feature placement, depth planes, setups) are
  // shared exactly, the first kNamedShared distinct values of each: programs return to few
  // depths and places, but a streamed file must not remember every one of a pathological
  // program (later new values are written where used). Unnamed placements of arcs are shared
  // while remembered.
  std::uint64_t name_index(std::string_view name) {
    for (std::size_t i = 0; i < names_.size(); ++i) {
      if (names_[i] == name) return i;
    }
    names_.emplace_back(name);
    return names_.size() - 1;
  }
  InstanceId placement(const sn::Axis2Placement3d& a, std::string_view name) {
    const PlacementKey key = key_of(name_index(name), a);
    if (const InstanceId id = recent_placements_.find(key)) return id;
    InstanceId id = 0;
    if (auto it = placements_.find(key); it != placements_.end()) {
      id = it->second;
    } else {
      id = new_placement(a, name);
      if (placements_.size() >= kNamedShared) return id;
      placements_.emplace(key, id);
    }
    recent_placements_.remember(key, id);
    return id;
  }
  InstanceId plane(const sn::Plane& pl, std::string_view name) {
    const PlacementKey key = key_of(name_index(name), pl.position);
    if (const InstanceId id = recent_planes_.find(key)) return id;
    if (auto it = planes_.find(key); it != planes_.end()) {
      recent_planes_.remember(key, it->second);
      return it->second;
    }
    const InstanceId position = placement(pl.position, name);
    s_.begin("PLANE");
    s_.string(name);
    s_.ref(position);
    const InstanceId id = s_.end();
    if (planes_.size() < kNamedShared) {
      planes_.emplace(key, id);
      recent_planes_.remember(key, id);
    }
    return id;
  }
  InstanceId arc_placement(const sn::Axis2Placement3d& a) {
    const InstanceId location = point(a.location);
    const InstanceId axis = direction(a.axis);
    const InstanceId ref_direction = direction(a.ref_direction);
    const Bits3 key{location, axis, ref_direction};
    if (const InstanceId id = arc_placements_.find(key)) return id;
    s_.begin("AXIS2_PLACEMENT_3D");
    s_.string("");
    s_.ref(location);
    s_.ref(axis);
    s_.ref(ref_direction);
    const InstanceId id = s_.end();
    arc_placements_.remember(key, id);
    return id;
  }
  InstanceId circle(const sn::TrimmedCircle& t) {
    const InstanceId position = arc_placement(t.position);
    const std::array<std::uint64_t, 2> key{position, part21::RecentInstances<2>::bits(t.radius)};
    if (const InstanceId id = circles_.find(key)) return id;
    s_.begin("CIRCLE");
    s_.string("");
    s_.ref(position);
    s_.real(t.radius);
    const InstanceId id = s_.end();
    circles_.remember(key, id);
    return id;
  }

  InstanceId polyline(const sn::Polyline& l) {
    if (l.points.empty()) throw std::invalid_argument("write_stepnc: a POLYLINE needs at least one point");
    polyline_points_.clear();
    for (const auto& c : l.points) polyline_points_.push_back(point(c));
    s_.begin("POLYLINE");
    s_.string("");
    s_.refs(polyline_points_);
    return s_.end();
  }
  InstanceId trimmed_circle(const sn::TrimmedCircle& t) {
    const InstanceId basis = circle(t);
    const InstanceId p1 = point(t.trim_1_point);
    const InstanceId p2 = point(t.trim_2_point);
    s_.begin("TRIMMED_CURVE");
    s_.string("");
    s_.ref(basis);
    s_.open_list();
    s_.ref(p1);
    s_.typed_real("PARAMETER_VALUE", t.trim_1_parameter);
    s_.close_list();
    s_.open_list();
    s_.ref(p2);
    s_.typed_real("PARAMETER_VALUE", t.trim_2_parameter);
    s_.close_list();
    s_.boolean(t.sense_agreement);
    s_.enumeration("PARAMETER");
    return s_.end();
  }
  // B_SPLINE_CURVE_WITH_KNOTS; with weights, the complex instance of it and
  // RATIONAL_B_SPLINE_CURVE (with the supertypes, which carry no attributes in this schema).
  InstanceId bspline(const sn::BSplineCurve& b) {
    if (const std::string problem = sn::bspline_problem(b); !problem.empty()) {
      throw std::invalid_argument("write_stepnc: a B_SPLINE_CURVE_WITH_KNOTS that is no B-spline: " + problem);
    }
    polyline_points_.clear();
    for (const auto& c : b.control_points) polyline_points_.push_back(point(c));
    const bool closed = b.control_points.front() == b.control_points.back();
    auto b_spline_curve = [&] {
      s_.string("");
      s_.integer(b.degree);
      s_.refs(polyline_points_);
      s_.enumeration("UNSPECIFIED");
      s_.boolean(closed);
      s_.unknown();
    };
    auto with_knots = [&] {
      s_.open_list();
      for (int m : b.knot_multiplicities) s_.integer(m);
      s_.close_list();
      s_.open_list();
      for (double k : b.knots) s_.real(k);
      s_.close_list();
      s_.enumeration(knot_type_name(b.knot_spec));
    };
    if (b.weights.empty()) {
      s_.begin("B_SPLINE_CURVE_WITH_KNOTS");
      b_spline_curve();
      with_knots();
      return s_.end();
    }
    const InstanceId id = s_.begin_complex();
    for (std::string_view empty : {"BOUNDED_CURVE"}) {
      s_.record(empty);
      s_.end_record();
    }
    s_.record("B_SPLINE_CURVE");
    b_spline_curve();
    s_.end_record();
    s_.record("B_SPLINE_CURVE_WITH_KNOTS");
    with_knots();
    s_.end_record();
    for (std::string_view empty : {"CURVE", "GEOMETRIC_REPRESENTATION_ITEM"}) {
      s_.record(empty);
      s_.end_record();
    }
    s_.record("RATIONAL_B_SPLINE_CURVE");
    s_.open_list();
    for (double w : b.weights) s_.real(w);
    s_.close_list();
    s_.end_record();
    s_.record("REPRESENTATION_ITEM");
    s_.end_record();
    s_.end();
    return id;
  }
  InstanceId curve(const sn::CompositeCurve& c) {
    if (c.segments.size() == 1) {
      if (const auto* l = std::get_if<sn::Polyline>(&c.segments[0])) return polyline(*l);
    }
    std::vector<InstanceId>& segments = segment_ids_;
    segments.clear();
    for (std::size_t i = 0; i < c.segments.size(); ++i) {
      const InstanceId parent = std::visit(Overload{[&](const sn::Polyline& l) { return polyline(l); },
                                                    [&](const sn::TrimmedCircle& t) { return trimmed_circle(t); },
                                                    [&](const sn::BSplineCurve& b) { return bspline(b); }},
                                           c.segments[i]);
      s_.begin("COMPOSITE_CURVE_SEGMENT");
      s_.enumeration(i + 1 == c.segments.size() ? "DISCONTINUOUS" : "CONTINUOUS");
      s_.boolean(true);
      s_.ref(parent);
      segments.push_back(s_.end());
    }
    s_.begin("COMPOSITE_CURVE");
    s_.string("");
    s_.refs(segments);
    s_.enumeration("F");
    return s_.end();
  }

  // ---- resources
  InstanceId tool(sn::ToolRef r) {
    InstanceId& id = written(tools_, r.index, p_->tools.size());
    if (id != 0) return id;
    const sn::MillingCuttingTool& t = p_->tool(r);
    const auto& d = t.dimension;
    s_.begin("MILLING_TOOL_DIMENSION");
    s_.real(d.diameter);
    s_.opt_real(d.tool_tip_half_angle);
    s_.opt_real(d.tool_circumference_angle);
    s_.opt_real(d.cutting_edge_length);
    s_.opt_real(d.edge_radius);
    s_.opt_real(d.edge_center_vertical);
    s_.opt_real(d.edge_center_horizontal);
    const InstanceId dimension = s_.end();

    s_.begin(tool_body_entity(t.body));
    s_.ref(dimension);
    t.number_of_teeth ? s_.integer(*t.number_of_teeth) : s_.unset();
    if (t.hand_of_cut) {
      s_.enumeration(*t.hand_of_cut == sn::Hand::Left ? "LEFT" : *t.hand_of_cut == sn::Hand::Right ? "RIGHT" : "NEUTRAL");
    } else {
      s_.unset();
    }
    s_.opt_boolean(t.coolant_through_tool);
    s_.opt_real(t.pilot_length);
    switch (t.body) {
      case sn::ToolBody::TSlotMill: case sn::ToolBody::Countersink: s_.unset(); break;
      case sn::ToolBody::BoringTool: s_.boolean(false); break;
      case sn::ToolBody::UserDefinedTool: s_.string(t.its_id); break;
      default: break;
    }
    const InstanceId body = s_.end();

    s_.begin("CUTTING_COMPONENT");
    s_.real(t.tool_offset_length);
    for (int k = 0; k < 4; ++k) s_.unset();
    const InstanceId component = s_.end();

    s_.begin("MILLING_CUTTING_TOOL");
    s_.string(t.its_id);
    s_.ref(body);
    s_.refs(std::array{component});
    s_.opt_real(t.overall_assembly_length);
    s_.unset();
    s_.unset();
    return id = s_.end();
  }
  InstanceId technology(sn::TechnologyRef r) {
    InstanceId& id = written(technologies_, r.index, p_->technologies.size());
    if (id != 0) return id;
    const sn::MillingTechnology& t = p_->technology(r);
    s_.begin("MILLING_TECHNOLOGY");
    s_.opt_real(t.feedrate);
    s_.enumeration(t.feedrate_reference == sn::ToolReferencePoint::Tcp ? "TCP" : "CCP");
    s_.opt_real(t.cutspeed);
    s_.opt_real(t.spindle);
    s_.opt_real(t.feedrate_per_tooth);
    s_.boolean(t.synchronize_spindle_with_feed);
    s_.boolean(t.inhibit_feedrate_override);
    s_.boolean(t.inhibit_spindle_override);
    s_.unset();
    return id = s_.end();
  }
  InstanceId functions(sn::MachineFunctionsRef r) {
    InstanceId& id = written(functions_, r.index, p_->machine_functions.size());
    if (id != 0) return id;
    const sn::MillingMachineFunctions& f = p_->functions(r);
    s_.begin("MILLING_MACHINE_FUNCTIONS");
    s_.boolean(f.coolant);
    s_.opt_real(f.coolant_pressure);
    s_.opt_boolean(f.mist);
    s_.boolean(f.through_spindle_coolant);
    s_.opt_real(f.through_pressure);
    s_.open_list();
    s_.close_list();
    s_.boolean(f.chip_removal);
    s_.unset();
    s_.unset();
    s_.open_list();
    s_.close_list();
    return id = s_.end();
  }

  // ---- toolpaths
  InstanceId toolpath_list(const sn::ToolpathList& l) {
    std::vector<InstanceId>& items = trajectory_ids_;
    items.clear();
    for (const auto& t : l.its_list) {
      const InstanceId basic = curve(t.basiccurve);
      const InstanceId tech = t.its_technology ? technology(*t.its_technology) : 0;
      const InstanceId fn = t.its_machine_functions ? functions(*t.its_machine_functions) : 0;
      s_.begin("CUTTER_LOCATION_TRAJECTORY");
      s_.boolean(t.its_priority);
      s_.enumeration(toolpath_type_name(t.its_type));
      s_.unset();
      s_.opt_ref(tech);
      s_.opt_ref(fn);
      s_.opt_boolean(t.its_direction);
      s_.ref(basic);
      s_.unset();
      s_.unset();
      items.push_back(s_.end());
    }
    s_.begin("TOOLPATH_LIST");
    s_.refs(items);
    return s_.end();
  }

  // ---- operations
  InstanceId drilling_strategy(const sn::DrillingTypeOperation& op) {
    if (!op.its_machining_strategy) return 0;
    const auto& s = *op.its_machining_strategy;
    s_.begin("DRILLING_TYPE_STRATEGY");
    s_.opt_real(s.reduced_cut_at_start);
    s_.opt_real(s.reduced_feed_at_start);
    s_.opt_real(s.depth_of_start);
    s_.opt_real(s.reduced_cut_at_end);
    s_.opt_real(s.reduced_feed_at_end);
    s_.opt_real(s.depth_of_end);
    return s_.end();
  }
  void drilling_attributes(const sn::DrillingTypeOperation& op, InstanceId strategy) {
    s_.opt_real(op.cutting_depth);
    s_.opt_real(op.previous_diameter);
    s_.opt_real(op.dwell_time_bottom);
    s_.opt_real(op.feed_on_retract);
    s_.opt_ref(strategy);
  }
  InstanceId milling_strategy(const sn::Two5DMillingOperation& op) {
    if (!op.its_machining_strategy) return 0;
    auto cutmode = [&](const std::optional<sn::CutmodeType>& c) {
      c ? s_.enumeration(*c == sn::CutmodeType::Climb ? "CLIMB" : "CONVENTIONAL") : s_.unset();
    };
    auto rotation = [&](const std::optional<sn::RotDirection>& r) {
      r ? s_.enumeration(*r == sn::RotDirection::Cw ? "CW" : "CCW") : s_.unset();
    };
    auto feed_direction = [&](const std::optional<sn::Direction>& d) { return d ? direction(*d) : InstanceId{0}; };
    return std::visit(Overload{
        [&](const sn::Unidirectional& u) {
          const InstanceId dir = feed_direction(u.feed_direction);
          s_.begin("UNIDIRECTIONAL");
          s_.unset();
          s_.unset();
          s_.opt_ref(dir);
          cutmode(u.cutmode);
          return s_.end();
        },
        [&](const sn::Bidirectional& b) {
          const InstanceId dir = feed_direction(b.feed_direction);
          s_.begin("BIDIRECTIONAL");
          s_.unset();
          s_.unset();
          s_.opt_ref(dir);
          if (b.stepover_direction) {
            s_.enumeration(*b.stepover_direction == sn::LeftOrRight::Left ? "LEFT" : "RIGHT");
          } else {
            s_.unset();
          }
          s_.unset();
          return s_.end();
        },
        [&](const sn::ContourParallel& c) {
          s_.begin("CONTOUR_PARALLEL");
          s_.unset();
          s_.unset();
          rotation(c.rotation_direction);
          cutmode(c.cutmode);
          return s_.end();
        },
        [&](const sn::ContourSpiral& c) {
          s_.begin("CONTOUR_SPIRAL");
          s_.unset();
          s_.unset();
          rotation(c.rotation_direction);
          cutmode(c.cutmode);
          return s_.end();
        },
        [&](const sn::CenterMilling&) {
          s_.begin("CENTER_MILLING");
          s_.unset();
          s_.unset();
          return s_.end();
        }},
        *op.its_machining_strategy);
  }
  void two5d_attributes(const sn::Two5DMillingOperation& op, InstanceId strategy, bool plane, bool side) {
    s_.unset();  // approach
    s_.unset();  // retract
    s_.opt_ref(strategy);
    s_.opt_real(op.axial_cutting_depth);
    if (side) {
      s_.opt_real(op.radial_cutting_depth);
      s_.opt_real(op.allowance_side);
    }
    if (plane) s_.opt_real(op.allowance_bottom);
  }

  InstanceId operation(sn::OperationRef r) {
    InstanceId& id = written(operations_, r.index, p_->operations.size());
    if (id == 0) id = operation_instance(p_->operation(r));
    return id;
  }
  InstanceId operation_instance(const sn::Operation& op) {
    const sn::MachiningOperation& m = sn::machining_operation(op);
    const InstanceId toolpath = m.its_toolpath ? toolpath_list(*m.its_toolpath) : 0;
    const InstanceId start = m.start_point ? point(*m.start_point) : 0;
    const InstanceId tool_id = tool(m.its_tool);
    const InstanceId technology_id = technology(m.its_technology);
    const InstanceId functions_id = functions(m.its_machine_functions);
    return std::visit(
        [&](const auto& o) {
          using O = std::decay_t<decltype(o)>;
          // Instances the subtype's own attributes refer to come first.
          InstanceId strategy = 0, waiting = 0;
          if constexpr (std::is_base_of_v<sn::DrillingTypeOperation, O>) strategy = drilling_strategy(o);
          if constexpr (std::is_base_of_v<sn::Two5DMillingOperation, O>) strategy = milling_strategy(o);
          if constexpr (std::is_base_of_v<sn::BoringOperation, O>) waiting = o.waiting_position ? point(*o.waiting_position) : 0;

          s_.begin(sn::entity_name(op));
          s_.opt_ref(toolpath);
          s_.unset();
          s_.string(m.its_id);
          s_.opt_real(m.retract_plane);
          s_.opt_ref(start);
          s_.ref(tool_id);
          s_.ref(technology_id);
          s_.ref(functions_id);
          s_.opt_real(m.overcut_length);
          if constexpr (std::is_same_v<O, sn::FreeformOperation>) {
            s_.unset();
            s_.unset();
            s_.unset();
          } else if constexpr (std::is_same_v<O, sn::MultistepDrilling>) {
            drilling_attributes(o, strategy);
            s_.real(o.retract_distance);
            s_.real(o.first_depth);
            s_.real(o.depth_of_step);
            s_.opt_real(o.dwell_time_step);
          } else if constexpr (std::is_base_of_v<sn::BoringOperation, O>) {
            drilling_attributes(o, strategy);
            s_.boolean(o.spindle_stop_at_bottom);
            s_.opt_real(o.depth_of_testcut);
            s_.opt_ref(waiting);
          } else if constexpr (std::is_same_v<O, sn::Tapping>) {
            drilling_attributes(o, strategy);
            s_.boolean(o.compensation_chuck);
          } else if constexpr (std::is_base_of_v<sn::DrillingTypeOperation, O>) {
            drilling_attributes(o, strategy);
          } else if constexpr (std::is_same_v<O, sn::PlaneRoughMilling> || std::is_same_v<O, sn::PlaneFinishMilling>) {
            two5d_attributes(o, strategy, true, false);
          } else if constexpr (std::is_same_v<O, sn::SideRoughMilling> || std::is_same_v<O, sn::SideFinishMilling>) {
            two5d_attributes(o, strategy, false, true);
          } else {
            static_assert(std::is_base_of_v<sn::Two5DMillingOperation, O>);
            two5d_attributes(o, strategy, true, true);
          }
          return s_.end();
        },
        op);
  }

  // ---- features
  InstanceId toleranced(const sn::TolerancedLengthMeasure& t) {
    s_.begin("PLUS_MINUS_VALUE");
    s_.real(t.upper_limit);
    s_.real(t.lower_limit);
    s_.integer(t.significant_digits);
    const InstanceId tolerance = s_.end();
    s_.begin("TOLERANCED_LENGTH_MEASURE");
    s_.real(t.theoretical_size);
    s_.ref(tolerance);
    return s_.end();
  }
  InstanceId hole_bottom(const sn::HoleBottomCondition& b) {
    std::visit(Overload{[&](const sn::ThroughBottomCondition&) { s_.begin("THROUGH_BOTTOM_CONDITION"); },
                        [&](const sn::FlatHoleBottom&) { s_.begin("FLAT_HOLE_BOTTOM"); },
                        [&](const sn::ConicalHoleBottom& c) {
                          s_.begin("CONICAL_HOLE_BOTTOM");
                          s_.real(c.tip_angle);
                          s_.unset();
                        }},
               b);
    return s_.end();
  }

  InstanceId feature(sn::FeatureRef r) {
    InstanceId& id = written(features_, r.index, p_->features.size());
    if (id != 0) return id;
    std::vector<InstanceId>& ops = feature_operation_ids_;
    ops.clear();
    for (std::uint32_t k = feature_first_[r.index]; k < feature_first_[r.index + 1]; ++k) ops.push_back(operation(feature_ops_[k]));
    return id = feature_instance(p_->feature(r), ops);
  }
  InstanceId feature_instance(const sn::Feature& f, const std::vector<InstanceId>& ops) {
    if (cc2::is_cc2_feature(f)) {  // cc2_writer.cpp, sharing this writer's geometry
      struct Geometry final : cc2::SharedGeometry {
        explicit Geometry(Cc1Writer& writer) : w(writer) {}
        InstanceId placement(const sn::Axis2Placement3d& a, std::string_view name) override { return w.placement(a, name); }
        InstanceId plane(const sn::Plane& p, std::string_view name) override { return w.plane(p, name); }
        InstanceId direction(const sn::Direction& d) override { return w.direction(d); }
        InstanceId curve(const sn::CompositeCurve& c) override { return w.curve(c); }
        InstanceId toleranced(const sn::TolerancedLengthMeasure& t) override { return w.toleranced(t); }
        Cc1Writer& w;
      } geometry(*this);
      return cc2::write_feature(s_, geometry, f, workpiece_, ops);
    }
    // MACHINING_FEATURE's attributes; CC2 features are written by their own mapping (issue 4): a
    // CC1 file carries them as toolpath features so it stays valid.
    struct Common {
      std::string_view id;
      InstanceId placement, depth;
    };
    auto common = [&](const std::string& id, const sn::Axis2Placement3d& placement_value, const sn::Plane& depth) {
      const InstanceId placement_id = placement(placement_value, "FEATURE PLACEMENT");
      const InstanceId depth_id = plane(depth, "DEPTH PLANE");
      return Common{id, placement_id, depth_id};
    };
    auto write_common = [&](std::string_view entity, const Common& c) {
      s_.begin(entity);
      s_.string(c.id);
      s_.ref(workpiece_);
      s_.refs(ops);
      s_.ref(c.placement);
      s_.ref(c.depth);
    };
    std::visit(Overload{
        [&](const sn::RoundHole& h) {
          const Common c = common(h.its_id, h.feature_placement, h.depth);
          const InstanceId diameter = toleranced(h.diameter);
          const InstanceId bottom = hole_bottom(h.bottom_condition);
          write_common("ROUND_HOLE", c);
          s_.ref(diameter);
          s_.unset();
          s_.ref(bottom);
        },
        [&](const sn::Region& g) {
          write_common("TOOLPATH_FEATURE", common(g.its_id, g.feature_placement.value_or(sn::Axis2Placement3d{}), sn::Plane{}));
        },
        [&](const sn::MachiningFeature& m) {
          write_common("TOOLPATH_FEATURE", common(m.its_id, m.feature_placement, m.depth));
        }},
        f);
    return s_.end();
  }

  // ---- workplan
  // The setup's security plane (reserved, written by write_setup) or another one.
  InstanceId security_plane(const sn::Plane& pl) {
    return streamed_ || pl == p_->setup.its_secplane ? security_plane_ : plane(pl, "SECURITY PLANE");
  }

  InstanceId write_executable(const sn::MachiningWorkingstep& ws) {
    const InstanceId secplane = security_plane(ws.its_secplane);
    InstanceId feature_id = 0, operation_id = 0;
    if (streamed_) {  // its own feature and operation, in the order a whole project writes them
      operation_id = operation_instance(p_->operation(ws.its_operation));
      feature_operation_ids_.assign(1, operation_id);
      feature_id = feature_instance(p_->feature(ws.its_feature), feature_operation_ids_);
    } else {
      feature_id = feature(ws.its_feature);
      operation_id = operation(ws.its_operation);
    }
    s_.begin("MACHINING_WORKINGSTEP");
    s_.string(ws.its_id);
    s_.ref(secplane);
    s_.ref(feature_id);
    s_.ref(operation_id);
    s_.unset();
    return s_.end();
  }
  InstanceId write_executable(const sn::RapidMovement& r) {
    const InstanceId secplane = security_plane(r.its_secplane);
    const InstanceId toolpath = r.its_toolpath ? toolpath_list(*r.its_toolpath) : 0;
    s_.begin("RAPID_MOVEMENT");
    s_.string(r.its_id);
    s_.ref(secplane);
    s_.opt_ref(toolpath);
    s_.unset();
    return s_.end();
  }

  InstanceId write_executable(const sn::WorkpieceProbing& w) {
    const InstanceId secplane = security_plane(w.its_secplane);
    s_.begin("NC_VARIABLE");
    s_.string(w.measured_offset.its_name);
    s_.opt_real(w.measured_offset.initial_value);
    const InstanceId variable = s_.end();
    const InstanceId start = placement(w.start_position, "PROBING START");
    const InstanceId direction_id = direction(w.its_direction);
    const InstanceId expected = toleranced(w.expected_value);
    InstanceId& probe = touch_probes_[w.its_probe];
    if (probe == 0) {
      s_.begin("TOUCH_PROBE");
      s_.string(w.its_probe);
      probe = s_.end();
    }
    s_.begin("WORKPIECE_PROBING");
    s_.string(w.its_id);
    s_.ref(secplane);
    s_.unset();  // its_toolpath: the probing move is described by the attributes below
    s_.unset();  // its_tool_direction
    s_.ref(variable);
    s_.ref(start);
    s_.ref(workpiece_);
    s_.ref(direction_id);
    s_.ref(expected);
    s_.ref(probe);
    return s_.end();
  }

  InstanceId write_workpiece(const sn::Workpiece& w, InstanceId rawpiece) {
    InstanceId bounding = 0;
    if (w.its_bounding_geometry) {
      const auto& b = *w.its_bounding_geometry;
      const InstanceId position = placement(b.position, w.its_id);
      s_.begin("BLOCK");
      s_.string(w.its_id);
      s_.ref(position);
      s_.real(b.x);
      s_.real(b.y);
      s_.real(b.z);
      bounding = s_.end();
    }
    std::vector<InstanceId> clamps;
    for (const auto& c : w.clamping_positions) clamps.push_back(point(c));
    s_.begin("WORKPIECE");
    s_.string(w.its_id);
    s_.unset();
    s_.opt_real(w.global_tolerance);
    s_.opt_ref(rawpiece);
    s_.unset();
    s_.opt_ref(bounding);
    s_.refs(clamps);
    return s_.end();
  }

  InstanceId write_setup() {
    const sn::Setup& s = p_->setup;
    const InstanceId origin = s.its_origin ? placement(*s.its_origin, s.its_id) : 0;
    const InstanceId secplane_position = placement(s.its_secplane.position, "SECURITY PLANE");
    s_.begin(security_plane_, "PLANE");
    s_.string("SECURITY PLANE");
    s_.ref(secplane_position);
    const InstanceId secplane = s_.end();
    const InstanceId wp_origin = placement(s.its_workpiece_setup.its_origin, p_->workpiece.its_id);
    s_.begin("WORKPIECE_SETUP");
    s_.ref(workpiece_);
    s_.ref(wp_origin);
    s_.unset();
    s_.unset();
    s_.open_list();
    s_.close_list();
    const InstanceId wp_setup = s_.end();
    s_.begin("SETUP");
    s_.string(s.its_id);
    s_.opt_ref(origin);
    s_.ref(secplane);
    s_.refs(std::array{wp_setup});
    return s_.end();
  }

  const sn::Project* p_ = nullptr;
  InstanceStream& s_;
  bool streamed_;
  InstanceId workpiece_ = 0, security_plane_ = 0;
  part21::InstanceIdList executables_;
  std::vector<std::uint32_t> feature_first_;
  std::vector<sn::OperationRef> feature_ops_;
  std::vector<InstanceId> tools_, technologies_, functions_, operations_, features_;  // 0: not written yet
  std::vector<std::string> names_;  // of named placements and planes (few: ids of setups and workpieces, roles)
  static constexpr std::size_t kNamedShared = 16384;
  std::unordered_map<PlacementKey, InstanceId, PlacementKeyHash> placements_, planes_;
  part21::RecentInstances<10> recent_placements_{6}, recent_planes_{6};  // the maps' entries used last
  part21::RecentInstances<3> points_{12}, directions_{10}, arc_placements_{10};
  part21::RecentInstances<2> circles_{10};
  // Scratch lists, one per level of nesting (curve <- toolpath list <- operation <- feature).
  std::vector<InstanceId> polyline_points_, segment_ids_, trajectory_ids_, feature_operation_ids_;
  std::unordered_map<std::string, InstanceId> touch_probes_;  // TOUCH_PROBE by its_id (few in a program)
};

std::string header_text(const StepncWriteOptions& options) {
  part21::Graph header_only;
  header_only.header.description = options.description;
  header_only.header.name = options.file_name;
  const std::string ncbridge(version_string());
  header_only.header.preprocessor_version = options.preprocessor_version.empty() ? ncbridge : options.preprocessor_version;
  header_only.header.originating_system = options.originating_system.empty() ? ncbridge : options.originating_system;
  header_only.header.schema = {"MACHINING_SCHEMA", "MILLING_SCHEMA"};
  if (options.unix_time) header_only.header.time_stamp = part21::time_stamp_of(*options.unix_time);
  // The header as the generic writer writes it, up to the DATA section it opens.
  std::string text = part21::write_part21(header_only);
  const std::size_t data = text.rfind("DATA;\n");
  if (data == std::string::npos) throw std::logic_error("write_stepnc: unexpected Part 21 writer output");
  text.resize(data + 6);
  return text;
}

}  // namespace

std::uint64_t write_stepnc(const stepnc::Project& project, const StepncWriteOptions& options,
                           const std::function<void(std::string_view)>& write_chunk) {
  InstanceStream stream(write_chunk);
  stream.raw(header_text(options));
  Cc1Writer writer(stream, Cc1Writer::Mode::Whole);
  writer.begin(project);
  for (const auto& e : project.main_workplan.its_elements) writer.element(project, e);
  writer.finish(project);
  stream.raw("ENDSEC;\nEND-ISO-10303-21;\n");
  return stream.finish();
}

struct StepncStreamWriter::Impl {
  Impl(const StepncWriteOptions& options, std::function<void(std::string_view)> write_chunk)
      : sink(std::move(write_chunk)), stream(sink), writer(stream, Cc1Writer::Mode::Streamed) {
    stream.raw(header_text(options));
  }
  void begin_once(const stepnc::Project& project) {
    if (begun) return;
    begun = true;
    writer.begin(project);
  }
  std::function<void(std::string_view)> sink;
  InstanceStream stream;
  Cc1Writer writer;
  bool begun = false;
  bool finished = false;
};

StepncStreamWriter::StepncStreamWriter(const StepncWriteOptions& options, std::function<void(std::string_view)> write_chunk)
    : impl_(std::make_unique<Impl>(options, std::move(write_chunk))) {}
StepncStreamWriter::~StepncStreamWriter() = default;

void StepncStreamWriter::element(const stepnc::Project& project, const stepnc::Executable& element) {
  if (impl_->finished) throw std::logic_error("StepncStreamWriter: element() after finish()");
  impl_->begin_once(project);
  impl_->writer.element(project, element);
}

std::uint64_t StepncStreamWriter::finish(const stepnc::Project& project) {
  if (impl_->finished) throw std::logic_error("StepncStreamWriter: finish() called twice");
  impl_->finished = true;
  impl_->begin_once(project);
  impl_->writer.finish(project);
  impl_->stream.raw("ENDSEC;\nEND-ISO-10303-21;\n");
  return impl_->stream.finish();
}

std::string write_stepnc(const stepnc::Project& project, const StepncWriteOptions& options) {
  std::string text;
  write_stepnc(project, options, [&](std::string_view chunk) { text += chunk; });
  return text;
}

part21::Graph stepnc_to_graph(const stepnc::Project& project, const StepncWriteOptions& options) {
  // The instances exactly as written: the file text read back.
  return part21::read_part21(write_stepnc(project, options), options.file_name).graph;
}

}  // namespace ncbridge::step_writer
