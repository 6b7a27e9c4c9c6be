// ISO 14649 model -> Part 21 instance graph. Entity names and attribute orders follow the
// ISO 14649-10/-11/-111 drafts (reference/iso14649/combined_schema_iso14649_only.exp): inherited
// attributes first, `$` only for OPTIONAL attributes, `()` for empty required aggregates.
// Ids are given top-down (PROJECT #1, WORKPLAN #2, ...), each resource once, in first use order.
#include <map>
#include <tuple>
#include <type_traits>

#include "ncbridge/step_writer/part21_writer.hpp"
#include "ncbridge/step_writer/stepnc_file.hpp"

namespace ncbridge::step_writer {

namespace {

using namespace part21;
namespace sn = stepnc;

template <class... F> struct Overload : F... { using F::operator()...; };
template <class... F> Overload(F...) -> Overload<F...>;

Value opt_real(const std::optional<double>& v) { return v ? real(*v) : unset(); }
Value opt_bool(const std::optional<bool>& v) { return v ? boolean(*v) : unset(); }
Value opt_ref(std::optional<InstanceId> id) { return id ? ref(*id) : unset(); }

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

class Cc1Writer {
 public:
  explicit Cc1Writer(const sn::Project& p) : p_(p) {}

  Graph build(const StepncWriteOptions& options) {
    g_.header.description = options.description;
    g_.header.name = options.file_name;
    g_.header.schema = {"MACHINING_SCHEMA", "MILLING_SCHEMA"};
    if (options.unix_time) g_.header.time_stamp = time_stamp_of(*options.unix_time);

    // Which operations each feature carries (its_operations), in workplan order.
    feature_operations_.resize(p_.features.size());
    for (const auto& e : p_.main_workplan.its_elements) {
      if (const auto* ws = std::get_if<sn::MachiningWorkingstep>(&e)) {
        feature_operations_.at(ws->its_feature.index).push_back(ws->its_operation);
      }
    }

    const InstanceId project = g_.reserve();
    const InstanceId workplan = g_.reserve();
    workpiece_ = g_.reserve();
    const std::optional<InstanceId> rawpiece = p_.rawpiece ? std::optional(g_.reserve()) : std::nullopt;
    const InstanceId setup = g_.reserve();
    std::vector<InstanceId> executables;
    for (std::size_t i = 0; i < p_.main_workplan.its_elements.size(); ++i) executables.push_back(g_.reserve());

    g_.set(project, "PROJECT", {string(p_.its_id), ref(workplan), list_of_refs({workpiece_}), unset(), unset(), unset()});
    g_.set(workplan, "WORKPLAN", {string(p_.main_workplan.its_id), list_of_refs(executables), unset(), ref(setup), unset()});
    write_workpiece(workpiece_, p_.workpiece, rawpiece);
    if (rawpiece) write_workpiece(*rawpiece, *p_.rawpiece, std::nullopt);
    write_setup(setup);
    for (std::size_t i = 0; i < executables.size(); ++i) {
      std::visit([&](const auto& e) { write_executable(executables[i], e); }, p_.main_workplan.its_elements[i]);
    }
    return std::move(g_);
  }

 private:
  // ---- geometry
  InstanceId point(const sn::CartesianPoint& c, std::string name = "") {
    return g_.add("CARTESIAN_POINT", {string(std::move(name)), list({real(c.x), real(c.y), real(c.z)})});
  }
  InstanceId direction(const sn::Direction& d) {
    auto key = std::make_tuple(d.x, d.y, d.z);
    if (auto it = directions_.find(key); it != directions_.end()) return it->second;
    const InstanceId id = g_.add("DIRECTION", {string(""), list({real(d.x), real(d.y), real(d.z)})});
    directions_.emplace(key, id);
    return id;
  }
  InstanceId placement(const sn::Axis2Placement3d& a, std::string name = "") {
    const InstanceId location = point(a.location);
    return g_.add("AXIS2_PLACEMENT_3D",
                  {string(std::move(name)), ref(location), ref(direction(a.axis)), ref(direction(a.ref_direction))});
  }
  InstanceId plane(const sn::Plane& pl, const std::string& name) {
    auto key = std::make_tuple(name, pl.position.location.x, pl.position.location.y, pl.position.location.z,
                               pl.position.axis.x, pl.position.axis.y, pl.position.axis.z,
                               pl.position.ref_direction.x, pl.position.ref_direction.y, pl.position.ref_direction.z);
    if (auto it = planes_.find(key); it != planes_.end()) return it->second;
    const InstanceId position = placement(pl.position, name);
    const InstanceId id = g_.add("PLANE", {string(name), ref(position)});
    planes_.emplace(key, id);
    return id;
  }

  InstanceId polyline(const sn::Polyline& l) {
    std::vector<InstanceId> pts;
    pts.reserve(l.points.size());
    for (const auto& c : l.points) pts.push_back(point(c));
    return g_.add("POLYLINE", {string(""), list_of_refs(pts)});
  }
  InstanceId trimmed_circle(const sn::TrimmedCircle& t) {
    const InstanceId position = placement(t.position);
    const InstanceId circle = g_.add("CIRCLE", {string(""), ref(position), real(t.radius)});
    const InstanceId p1 = point(t.trim_1_point);
    const InstanceId p2 = point(t.trim_2_point);
    return g_.add("TRIMMED_CURVE", {string(""), ref(circle),
                                    list({ref(p1), typed("PARAMETER_VALUE", real(t.trim_1_parameter))}),
                                    list({ref(p2), typed("PARAMETER_VALUE", real(t.trim_2_parameter))}),
                                    boolean(t.sense_agreement), enumeration("PARAMETER")});
  }
  InstanceId curve(const sn::CompositeCurve& c) {
    if (c.segments.size() == 1) {
      if (const auto* l = std::get_if<sn::Polyline>(&c.segments[0])) return polyline(*l);
    }
    std::vector<InstanceId> segments;
    for (std::size_t i = 0; i < c.segments.size(); ++i) {
      const InstanceId parent = std::visit(Overload{[&](const sn::Polyline& l) { return polyline(l); },
                                                    [&](const sn::TrimmedCircle& t) { return trimmed_circle(t); }},
                                           c.segments[i]);
      const bool last = i + 1 == c.segments.size();
      segments.push_back(g_.add("COMPOSITE_CURVE_SEGMENT",
                                {enumeration(last ? "DISCONTINUOUS" : "CONTINUOUS"), boolean(true), ref(parent)}));
    }
    return g_.add("COMPOSITE_CURVE", {string(""), list_of_refs(segments), enumeration("F")});
  }

  // ---- resources
  InstanceId tool(sn::ToolRef r) {
    if (auto it = tools_.find(r.index); it != tools_.end()) return it->second;
    const sn::MillingCuttingTool& t = p_.tool(r);
    const auto& d = t.dimension;
    const InstanceId dimension = g_.add("MILLING_TOOL_DIMENSION",
        {real(d.diameter), opt_real(d.tool_tip_half_angle), opt_real(d.tool_circumference_angle),
         opt_real(d.cutting_edge_length), opt_real(d.edge_radius), opt_real(d.edge_center_vertical),
         opt_real(d.edge_center_horizontal)});
    std::vector<Value> body{ref(dimension), t.number_of_teeth ? integer(*t.number_of_teeth) : unset(),
                            t.hand_of_cut ? enumeration(*t.hand_of_cut == sn::Hand::Left    ? "LEFT"
                                                        : *t.hand_of_cut == sn::Hand::Right ? "RIGHT"
                                                                                            : "NEUTRAL")
                                          : unset(),
                            opt_bool(t.coolant_through_tool), opt_real(t.pilot_length)};
    switch (t.body) {
      case sn::ToolBody::TSlotMill: case sn::ToolBody::Countersink: body.push_back(unset()); break;
      case sn::ToolBody::BoringTool: body.push_back(boolean(false)); break;
      case sn::ToolBody::UserDefinedTool: body.push_back(string(t.its_id)); break;
      default: break;
    }
    const InstanceId body_id = g_.add(tool_body_entity(t.body), std::move(body));
    const InstanceId component = g_.add("CUTTING_COMPONENT", {real(t.tool_offset_length), unset(), unset(), unset(), unset()});
    const InstanceId id = g_.add("MILLING_CUTTING_TOOL", {string(t.its_id), ref(body_id), list_of_refs({component}),
                                                          opt_real(t.overall_assembly_length), unset(), unset()});
    tools_.emplace(r.index, id);
    return id;
  }
  InstanceId technology(sn::TechnologyRef r) {
    if (auto it = technologies_.find(r.index); it != technologies_.end()) return it->second;
    const sn::MillingTechnology& t = p_.technology(r);
    const InstanceId id = g_.add("MILLING_TECHNOLOGY",
        {opt_real(t.feedrate), enumeration(t.feedrate_reference == sn::ToolReferencePoint::Tcp ? "TCP" : "CCP"),
         opt_real(t.cutspeed), opt_real(t.spindle), opt_real(t.feedrate_per_tooth),
         boolean(t.synchronize_spindle_with_feed), boolean(t.inhibit_feedrate_override),
         boolean(t.inhibit_spindle_override), unset()});
    technologies_.emplace(r.index, id);
    return id;
  }
  InstanceId functions(sn::MachineFunctionsRef r) {
    if (auto it = functions_.find(r.index); it != functions_.end()) return it->second;
    const sn::MillingMachineFunctions& f = p_.functions(r);
    const InstanceId id = g_.add("MILLING_MACHINE_FUNCTIONS",
        {boolean(f.coolant), opt_real(f.coolant_pressure), opt_bool(f.mist), boolean(f.through_spindle_coolant),
         opt_real(f.through_pressure), list({}), boolean(f.chip_removal), unset(), unset(), list({})});
    functions_.emplace(r.index, id);
    return id;
  }

  // ---- toolpaths
  InstanceId toolpath_list(const sn::ToolpathList& l) {
    std::vector<InstanceId> items;
    for (const auto& t : l.its_list) {
      const InstanceId basic = curve(t.basiccurve);
      items.push_back(g_.add("CUTTER_LOCATION_TRAJECTORY",
          {boolean(t.its_priority), enumeration(toolpath_type_name(t.its_type)), unset(),
           t.its_technology ? ref(technology(*t.its_technology)) : unset(),
           t.its_machine_functions ? ref(functions(*t.its_machine_functions)) : unset(),
           opt_bool(t.its_direction), ref(basic), unset(), unset()}));
    }
    return g_.add("TOOLPATH_LIST", {list_of_refs(items)});
  }

  // ---- operations
  std::vector<Value> machining_operation_attributes(const sn::MachiningOperation& op) {
    const Value toolpath = op.its_toolpath ? ref(toolpath_list(*op.its_toolpath)) : unset();
    const Value start = op.start_point ? ref(point(*op.start_point)) : unset();
    return {toolpath, unset(), string(op.its_id), opt_real(op.retract_plane), start,
            ref(tool(op.its_tool)), ref(technology(op.its_technology)), ref(functions(op.its_machine_functions)),
            opt_real(op.overcut_length)};
  }
  void drilling_attributes(std::vector<Value>& a, const sn::DrillingTypeOperation& op) {
    a.push_back(opt_real(op.cutting_depth));
    a.push_back(opt_real(op.previous_diameter));
    a.push_back(opt_real(op.dwell_time_bottom));
    a.push_back(opt_real(op.feed_on_retract));
    if (op.its_machining_strategy) {
      const auto& s = *op.its_machining_strategy;
      a.push_back(ref(g_.add("DRILLING_TYPE_STRATEGY",
          {opt_real(s.reduced_cut_at_start), opt_real(s.reduced_feed_at_start), opt_real(s.depth_of_start),
           opt_real(s.reduced_cut_at_end), opt_real(s.reduced_feed_at_end), opt_real(s.depth_of_end)})));
    } else {
      a.push_back(unset());
    }
  }
  void two5d_attributes(std::vector<Value>& a, const sn::Two5DMillingOperation& op, bool plane, bool side) {
    a.push_back(unset());  // approach
    a.push_back(unset());  // retract
    a.push_back(op.its_machining_strategy ? strategy(*op.its_machining_strategy) : unset());
    a.push_back(opt_real(op.axial_cutting_depth));
    if (side) {
      a.push_back(opt_real(op.radial_cutting_depth));
      a.push_back(opt_real(op.allowance_side));
    }
    if (plane) a.push_back(opt_real(op.allowance_bottom));
  }
  Value strategy(const sn::Two5DMillingStrategy& s) {
    auto cutmode = [](const std::optional<sn::CutmodeType>& c) {
      return c ? enumeration(*c == sn::CutmodeType::Climb ? "CLIMB" : "CONVENTIONAL") : unset();
    };
    auto rot = [](const std::optional<sn::RotDirection>& r) { return r ? enumeration(*r == sn::RotDirection::Cw ? "CW" : "CCW") : unset(); };
    auto dir = [&](const std::optional<sn::Direction>& d) { return d ? ref(direction(*d)) : unset(); };
    return ref(std::visit(Overload{
        [&](const sn::Unidirectional& u) { return g_.add("UNIDIRECTIONAL", {unset(), unset(), dir(u.feed_direction), cutmode(u.cutmode)}); },
        [&](const sn::Bidirectional& b) {
          return g_.add("BIDIRECTIONAL", {unset(), unset(), dir(b.feed_direction),
                                          b.stepover_direction ? enumeration(*b.stepover_direction == sn::LeftOrRight::Left ? "LEFT" : "RIGHT") : unset(),
                                          unset()});
        },
        [&](const sn::ContourParallel& c) { return g_.add("CONTOUR_PARALLEL", {unset(), unset(), rot(c.rotation_direction), cutmode(c.cutmode)}); },
        [&](const sn::ContourSpiral& c) { return g_.add("CONTOUR_SPIRAL", {unset(), unset(), rot(c.rotation_direction), cutmode(c.cutmode)}); },
        [&](const sn::CenterMilling&) { return g_.add("CENTER_MILLING", {unset(), unset()}); }}, s));
  }

  InstanceId operation(sn::OperationRef r) {
    if (auto it = operations_.find(r.index); it != operations_.end()) return it->second;
    const sn::Operation& op = p_.operation(r);
    std::vector<Value> a = machining_operation_attributes(sn::machining_operation(op));
    std::visit(Overload{
        [&](const sn::FreeformOperation&) { a.insert(a.end(), {unset(), unset(), unset()}); },
        [&](const sn::MultistepDrilling& o) {
          drilling_attributes(a, o);
          a.insert(a.end(), {real(o.retract_distance), real(o.first_depth), real(o.depth_of_step), opt_real(o.dwell_time_step)});
        },
        [&](const sn::BoringOperation& o) {
          drilling_attributes(a, o);
          a.insert(a.end(), {boolean(o.spindle_stop_at_bottom), opt_real(o.depth_of_testcut),
                             o.waiting_position ? ref(point(*o.waiting_position)) : unset()});
        },
        [&](const sn::Tapping& o) {
          drilling_attributes(a, o);
          a.push_back(boolean(o.compensation_chuck));
        },
        [&](const sn::DrillingTypeOperation& o) { drilling_attributes(a, o); },
        [&](const sn::PlaneRoughMilling& o) { two5d_attributes(a, o, true, false); },
        [&](const sn::PlaneFinishMilling& o) { two5d_attributes(a, o, true, false); },
        [&](const sn::SideRoughMilling& o) { two5d_attributes(a, o, false, true); },
        [&](const sn::SideFinishMilling& o) { two5d_attributes(a, o, false, true); },
        [&](const sn::BottomAndSideRoughMilling& o) { two5d_attributes(a, o, true, true); },
        [&](const sn::BottomAndSideFinishMilling& o) { two5d_attributes(a, o, true, true); }},
        op);
    const InstanceId id = g_.add(sn::entity_name(op), std::move(a));
    operations_.emplace(r.index, id);
    return id;
  }

  // ---- features
  InstanceId toleranced(const sn::TolerancedLengthMeasure& t) {
    const InstanceId tol = g_.add("PLUS_MINUS_VALUE", {real(t.upper_limit), real(t.lower_limit), integer(t.significant_digits)});
    return g_.add("TOLERANCED_LENGTH_MEASURE", {real(t.theoretical_size), ref(tol)});
  }

  InstanceId feature(sn::FeatureRef r) {
    if (auto it = features_.find(r.index); it != features_.end()) return it->second;
    // Reserve first: the feature lists the operations that refer back to it.
    const InstanceId id = g_.reserve();
    features_.emplace(r.index, id);
    const sn::Feature& f = p_.feature(r);
    std::vector<InstanceId> ops;
    for (const auto& o : feature_operations_.at(r.index)) ops.push_back(operation(o));
    auto common = [&](const sn::MachiningFeature& m) {
      const InstanceId placement_id = placement(m.feature_placement, m.its_id);
      const InstanceId depth_id = plane(m.depth, m.its_id + " DEPTH PLANE");
      return std::vector<Value>{string(m.its_id), ref(workpiece_), list_of_refs(ops), ref(placement_id), ref(depth_id)};
    };
    std::visit(Overload{
        [&](const sn::ToolpathFeature& t) { g_.set(id, "TOOLPATH_FEATURE", common(t)); },
        [&](const sn::RoundHole& h) {
          auto a = common(h);
          a.push_back(ref(toleranced(h.diameter)));
          a.push_back(unset());
          a.push_back(ref(std::visit(Overload{
              [&](const sn::ThroughBottomCondition&) { return g_.add("THROUGH_BOTTOM_CONDITION", {}); },
              [&](const sn::FlatHoleBottom&) { return g_.add("FLAT_HOLE_BOTTOM", {}); },
              [&](const sn::ConicalHoleBottom& c) { return g_.add("CONICAL_HOLE_BOTTOM", {real(c.tip_angle), unset()}); }},
              h.bottom_condition)));
          g_.set(id, "ROUND_HOLE", std::move(a));
        },
        [&](const auto& other) {
          // CC2 features are written by the feature_recognizer's mapping (issue 4); a CC1 file
          // carries them as toolpath features so the file stays valid.
          auto a = common_of(other, common);
          g_.set(id, "TOOLPATH_FEATURE", std::move(a));
        }},
        f);
    return id;
  }
  template <class F, class Common>
  std::vector<Value> common_of(const F& f, Common& common) {
    if constexpr (std::is_base_of_v<sn::MachiningFeature, F>) {
      return common(f);
    } else {
      sn::MachiningFeature m;
      m.its_id = f.its_id;
      if (f.feature_placement) m.feature_placement = *f.feature_placement;
      return common(m);
    }
  }

  // ---- workplan
  void write_executable(InstanceId id, const sn::MachiningWorkingstep& ws) {
    const InstanceId secplane = plane(ws.its_secplane, "SECURITY PLANE");
    const InstanceId feature_id = feature(ws.its_feature);
    g_.set(id, "MACHINING_WORKINGSTEP", {string(ws.its_id), ref(secplane), ref(feature_id), ref(operation(ws.its_operation)), unset()});
  }
  void write_executable(InstanceId id, const sn::RapidMovement& r) {
    const InstanceId secplane = plane(r.its_secplane, "SECURITY PLANE");
    const Value toolpath = r.its_toolpath ? ref(toolpath_list(*r.its_toolpath)) : unset();
    g_.set(id, "RAPID_MOVEMENT", {string(r.its_id), ref(secplane), toolpath, unset()});
  }

  void write_workpiece(InstanceId id, const sn::Workpiece& w, std::optional<InstanceId> rawpiece) {
    Value bounding = unset();
    if (w.its_bounding_geometry) {
      const auto& b = *w.its_bounding_geometry;
      const InstanceId position = placement(b.position, w.its_id);
      bounding = ref(g_.add("BLOCK", {string(w.its_id), ref(position), real(b.x), real(b.y), real(b.z)}));
    }
    std::vector<InstanceId> clamps;
    for (const auto& c : w.clamping_positions) clamps.push_back(point(c, "CLAMPING POSITION"));
    g_.set(id, "WORKPIECE", {string(w.its_id), unset(), opt_real(w.global_tolerance), opt_ref(rawpiece), unset(),
                             bounding, list_of_refs(clamps)});
  }

  void write_setup(InstanceId id) {
    const sn::Setup& s = p_.setup;
    const Value origin = s.its_origin ? ref(placement(*s.its_origin, s.its_id)) : unset();
    const InstanceId secplane = plane(s.its_secplane, "SECURITY PLANE");
    const InstanceId wp_origin = placement(s.its_workpiece_setup.its_origin, p_.workpiece.its_id);
    const InstanceId wp_setup = g_.add("WORKPIECE_SETUP", {ref(workpiece_), ref(wp_origin), unset(), unset(), list({})});
    g_.set(id, "SETUP", {string(s.its_id), origin, ref(secplane), list_of_refs({wp_setup})});
  }

  const sn::Project& p_;
  Graph g_;
  InstanceId workpiece_ = 0;
  std::vector<std::vector<sn::OperationRef>> feature_operations_;
  std::map<std::tuple<double, double, double>, InstanceId> directions_;
  std::map<std::tuple<std::string, double, double, double, double, double, double, double, double, double>, InstanceId> planes_;
  std::map<std::uint32_t, InstanceId> tools_, technologies_, functions_, operations_, features_;
};

}  // namespace

part21::Graph stepnc_to_graph(const stepnc::Project& project, const StepncWriteOptions& options) {
  return Cc1Writer(project).build(options);
}

std::string write_stepnc(const stepnc::Project& project, const StepncWriteOptions& options) {
  part21::WriteOptions w;
  w.unix_time = options.unix_time;
  return part21::write_part21(stepnc_to_graph(project, options), w);
}

}  // namespace ncbridge::step_writer
