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

// Where instances go: a Graph (stepnc_to_graph) or straight into the file text (write_stepnc,
// which never holds the instance graph: a million-point toolpath stays cheap). Ids are
// consecutive from 1 and references only point back, so both give the same numbering.
class Emitter {
 public:
  virtual ~Emitter() = default;
  virtual InstanceId add(std::string_view entity, std::vector<Value> attributes) = 0;
  virtual InstanceId point(const sn::CartesianPoint& c) = 0;  // CARTESIAN_POINT('',(x,y,z))
  // POLYLINE('',(#first..#last)) over consecutive ids
  virtual InstanceId polyline(InstanceId first, InstanceId last) = 0;
};

class GraphEmitter final : public Emitter {
 public:
  explicit GraphEmitter(Graph& g) : g_(g) {}
  InstanceId add(std::string_view entity, std::vector<Value> attributes) override { return g_.add(entity, std::move(attributes)); }
  InstanceId point(const sn::CartesianPoint& c) override {
    return g_.add("CARTESIAN_POINT", {string(""), list({real(c.x), real(c.y), real(c.z)})});
  }
  InstanceId polyline(InstanceId first, InstanceId last) override {
    std::vector<InstanceId> ids;
    for (InstanceId i = first; i <= last; ++i) ids.push_back(i);
    return g_.add("POLYLINE", {string(""), list_of_refs(ids)});
  }

 private:
  Graph& g_;
};

class TextEmitter final : public Emitter {
 public:
  explicit TextEmitter(std::string& out) : out_(out) {}
  InstanceId add(std::string_view entity, std::vector<Value> attributes) override {
    start(entity);
    for (std::size_t i = 0; i < attributes.size(); ++i) {
      if (i) out_ += ',';
      out_ += format_value(attributes[i]);
    }
    return finish();
  }
  InstanceId point(const sn::CartesianPoint& c) override {
    start("CARTESIAN_POINT");
    out_ += "'',(";
    out_ += format_real(c.x);
    out_ += ',';
    out_ += format_real(c.y);
    out_ += ',';
    out_ += format_real(c.z);
    out_ += ')';
    return finish();
  }
  InstanceId polyline(InstanceId first, InstanceId last) override {
    start("POLYLINE");
    out_ += "'',(";
    std::size_t line_start = out_.size();
    for (InstanceId i = first; i <= last; ++i) {
      if (i != first) out_ += ',';
      if (out_.size() - line_start > 90) {  // keep lines readable: wrap long reference lists
        out_ += "\n  ";
        line_start = out_.size();
      }
      out_ += '#';
      out_ += std::to_string(i);
    }
    out_ += ')';
    return finish();
  }

 private:
  void start(std::string_view entity) {
    out_ += '#';
    out_ += std::to_string(next_);
    out_ += '=';
    out_ += entity;
    out_ += '(';
  }
  InstanceId finish() {
    out_ += ");\n";
    return next_++;
  }
  std::string& out_;
  InstanceId next_ = 1;
};

class Cc1Writer {
 public:
  Cc1Writer(const sn::Project& p, Emitter& out) : p_(p), g_(out) {}

  void build() {
    // Which operations each feature carries (its_operations), in workplan order.
    feature_operations_.resize(p_.features.size());
    for (const auto& e : p_.main_workplan.its_elements) {
      if (const auto* ws = std::get_if<sn::MachiningWorkingstep>(&e)) {
        feature_operations_.at(ws->its_feature.index).push_back(ws->its_operation);
      }
    }
    // Bottom-up: everything an instance refers to is written before it; PROJECT comes last.
    const std::optional<InstanceId> rawpiece =
        p_.rawpiece ? std::optional(write_workpiece(*p_.rawpiece, std::nullopt)) : std::nullopt;
    workpiece_ = write_workpiece(p_.workpiece, rawpiece);
    const InstanceId setup = write_setup();
    std::vector<InstanceId> executables;
    executables.reserve(p_.main_workplan.its_elements.size());
    for (const auto& e : p_.main_workplan.its_elements) {
      executables.push_back(std::visit([&](const auto& x) { return write_executable(x); }, e));
    }
    const InstanceId workplan = g_.add("WORKPLAN", {string(p_.main_workplan.its_id), list_of_refs(executables), unset(), ref(setup), unset()});
    g_.add("PROJECT", {string(p_.its_id), ref(workplan), list_of_refs({workpiece_}), unset(), unset(), unset()});
  }

 private:
  // ---- geometry
  InstanceId point(const sn::CartesianPoint& c) { return g_.point(c); }
  // The six axis directions are written once and shared; others (arc references) each once.
  InstanceId direction(const sn::Direction& d) {
    int slot = -1;
    const double c[3] = {d.x, d.y, d.z};
    for (int k = 0; k < 3; ++k) {
      if ((c[k] == 1 || c[k] == -1) && c[(k + 1) % 3] == 0 && c[(k + 2) % 3] == 0) slot = 2 * k + (c[k] < 0 ? 1 : 0);
    }
    if (slot >= 0 && axis_directions_[slot] != 0) return axis_directions_[slot];
    const InstanceId id = g_.add("DIRECTION", {string(""), list({real(d.x), real(d.y), real(d.z)})});
    if (slot >= 0) axis_directions_[slot] = id;
    return id;
  }
  // Placements and planes are shared between instances with the same name and value.
  using PlacementKey = std::tuple<std::string, double, double, double, double, double, double, double, double, double>;
  static PlacementKey key_of(const std::string& name, const sn::Axis2Placement3d& a) {
    return {name, a.location.x, a.location.y, a.location.z, a.axis.x, a.axis.y, a.axis.z,
            a.ref_direction.x, a.ref_direction.y, a.ref_direction.z};
  }
  InstanceId placement(const sn::Axis2Placement3d& a, std::string name = "") {
    auto key = key_of(name, a);
    if (auto it = placements_.find(key); it != placements_.end()) return it->second;
    const InstanceId id = new_placement(a, std::move(name));
    placements_.emplace(std::move(key), id);
    return id;
  }
  InstanceId new_placement(const sn::Axis2Placement3d& a, std::string name) {
    const InstanceId location = point(a.location);
    const InstanceId axis = direction(a.axis);
    const InstanceId ref_direction = direction(a.ref_direction);
    return g_.add("AXIS2_PLACEMENT_3D", {string(std::move(name)), ref(location), ref(axis), ref(ref_direction)});
  }
  InstanceId plane(const sn::Plane& pl, const std::string& name) {
    auto key = key_of(name, pl.position);
    if (auto it = planes_.find(key); it != planes_.end()) return it->second;
    const InstanceId position = placement(pl.position, name);
    const InstanceId id = g_.add("PLANE", {string(name), ref(position)});
    planes_.emplace(key, id);
    return id;
  }

  InstanceId polyline(const sn::Polyline& l) {
    const InstanceId first = point(l.points.at(0));
    InstanceId last = first;
    for (std::size_t i = 1; i < l.points.size(); ++i) last = point(l.points[i]);
    return g_.polyline(first, last);
  }
  InstanceId trimmed_circle(const sn::TrimmedCircle& t) {
    const InstanceId position = new_placement(t.position, "");
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
    InstanceId id = 0;
    const sn::Feature& f = p_.feature(r);
    std::vector<InstanceId> ops;
    for (const auto& o : feature_operations_.at(r.index)) ops.push_back(operation(o));
    auto common = [&](const sn::MachiningFeature& m) {
      const InstanceId placement_id = placement(m.feature_placement, "FEATURE PLACEMENT");
      const InstanceId depth_id = plane(m.depth, "DEPTH PLANE");
      return std::vector<Value>{string(m.its_id), ref(workpiece_), list_of_refs(ops), ref(placement_id), ref(depth_id)};
    };
    std::visit(Overload{
        [&](const sn::ToolpathFeature& t) { id = g_.add("TOOLPATH_FEATURE", common(t)); },
        [&](const sn::RoundHole& h) {
          auto a = common(h);
          a.push_back(ref(toleranced(h.diameter)));
          a.push_back(unset());
          a.push_back(ref(std::visit(Overload{
              [&](const sn::ThroughBottomCondition&) { return g_.add("THROUGH_BOTTOM_CONDITION", {}); },
              [&](const sn::FlatHoleBottom&) { return g_.add("FLAT_HOLE_BOTTOM", {}); },
              [&](const sn::ConicalHoleBottom& c) { return g_.add("CONICAL_HOLE_BOTTOM", {real(c.tip_angle), unset()}); }},
              h.bottom_condition)));
          id = g_.add("ROUND_HOLE", std::move(a));
        },
        [&](const auto& other) {
          // CC2 features are written by the feature_recognizer's mapping (issue 4); a CC1 file
          // carries them as toolpath features so the file stays valid.
          auto a = common_of(other, common);
          id = g_.add("TOOLPATH_FEATURE", std::move(a));
        }},
        f);
    features_.emplace(r.index, id);
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
  InstanceId write_executable(const sn::MachiningWorkingstep& ws) {
    const InstanceId secplane = plane(ws.its_secplane, "SECURITY PLANE");
    const InstanceId feature_id = feature(ws.its_feature);
    const InstanceId operation_id = operation(ws.its_operation);
    return g_.add("MACHINING_WORKINGSTEP", {string(ws.its_id), ref(secplane), ref(feature_id), ref(operation_id), unset()});
  }
  InstanceId write_executable(const sn::RapidMovement& r) {
    const InstanceId secplane = plane(r.its_secplane, "SECURITY PLANE");
    const Value toolpath = r.its_toolpath ? ref(toolpath_list(*r.its_toolpath)) : unset();
    return g_.add("RAPID_MOVEMENT", {string(r.its_id), ref(secplane), toolpath, unset()});
  }

  InstanceId write_workpiece(const sn::Workpiece& w, std::optional<InstanceId> rawpiece) {
    Value bounding = unset();
    if (w.its_bounding_geometry) {
      const auto& b = *w.its_bounding_geometry;
      const InstanceId position = placement(b.position, w.its_id);
      bounding = ref(g_.add("BLOCK", {string(w.its_id), ref(position), real(b.x), real(b.y), real(b.z)}));
    }
    std::vector<InstanceId> clamps;
    for (const auto& c : w.clamping_positions) clamps.push_back(point(c));
    return g_.add("WORKPIECE", {string(w.its_id), unset(), opt_real(w.global_tolerance), opt_ref(rawpiece), unset(),
                             bounding, list_of_refs(clamps)});
  }

  InstanceId write_setup() {
    const sn::Setup& s = p_.setup;
    const Value origin = s.its_origin ? ref(placement(*s.its_origin, s.its_id)) : unset();
    const InstanceId secplane = plane(s.its_secplane, "SECURITY PLANE");
    const InstanceId wp_origin = placement(s.its_workpiece_setup.its_origin, p_.workpiece.its_id);
    const InstanceId wp_setup = g_.add("WORKPIECE_SETUP", {ref(workpiece_), ref(wp_origin), unset(), unset(), list({})});
    return g_.add("SETUP", {string(s.its_id), origin, ref(secplane), list_of_refs({wp_setup})});
  }

  const sn::Project& p_;
  Emitter& g_;
  InstanceId workpiece_ = 0;
  std::vector<std::vector<sn::OperationRef>> feature_operations_;
  InstanceId axis_directions_[6] = {0, 0, 0, 0, 0, 0};
  std::map<PlacementKey, InstanceId> planes_, placements_;
  std::map<std::uint32_t, InstanceId> tools_, technologies_, functions_, operations_, features_;
};

}  // namespace

namespace {
Header header_of(const StepncWriteOptions& options) {
  Header h;
  h.description = options.description;
  h.name = options.file_name;
  h.schema = {"MACHINING_SCHEMA", "MILLING_SCHEMA"};
  if (options.unix_time) h.time_stamp = time_stamp_of(*options.unix_time);
  return h;
}
}  // namespace

part21::Graph stepnc_to_graph(const stepnc::Project& project, const StepncWriteOptions& options) {
  Graph g;
  g.header = header_of(options);
  GraphEmitter emitter(g);
  Cc1Writer(project, emitter).build();
  return g;
}

std::string write_stepnc(const stepnc::Project& project, const StepncWriteOptions& options) {
  // The header as the generic writer writes it (an empty DATA section follows it there).
  Graph header_only;
  header_only.header = header_of(options);
  std::string out = write_part21(header_only);
  const std::size_t data = out.rfind("DATA;\n");
  if (data == std::string::npos) throw std::logic_error("write_stepnc: unexpected Part 21 writer output");
  out.resize(data + 6);
  TextEmitter emitter(out);
  Cc1Writer(project, emitter).build();
  out += "ENDSEC;\nEND-ISO-10303-21;\n";
  return out;
}

}  // namespace ncbridge::step_writer
