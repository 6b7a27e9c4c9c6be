// Part 21 instance graph -> ISO 14649 model: the inverse of cc1_writer.cpp, and tolerant of the
// shapes real files have (NIST: tool bodies with a taper, bare POLYLINE toolpaths, strategies).
// CC1 and CC2 (the 2.5D milling features and operations of ISO 14649-10/-11). What the model
// cannot hold (bosses, approach strategies, other feature kinds) is reported as a warning; a
// file without a PROJECT, or with a reference to the wrong kind of entity, is an InputError
// naming the instance's line.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <map>
#include <optional>
#include <stdexcept>

#include "ncbridge/step_writer/part21_reader.hpp"
#include "ncbridge/step_writer/stepnc_file.hpp"

namespace ncbridge::step_writer {

namespace {

using namespace part21;
namespace sn = stepnc;

class Cc1Reader {
 public:
  Cc1Reader(const Graph& g, std::string file) : g_(g), file_(std::move(file)) {}

  StepncReadResult read() {
    const auto projects = g_.ids_of("PROJECT");
    if (projects.empty()) throw InputError({file_, 1, 1}, "no PROJECT instance: not an ISO 14649 program");
    const Instance& project = instance(projects.front());
    if (projects.size() > 1) warn(project, "more than one PROJECT: reading the first");
    auto& p = result_.project;
    p.its_id = text(project, 0);
    const auto workpieces = list(project, 2);
    if (!workpieces.empty()) {
      const Instance& wp = expect(reference_in(workpieces.front(), project), {"WORKPIECE"}, project);
      workpiece_id_ = wp.id;
      p.workpiece = workpiece(wp);
      if (!attr(wp, 3).is_unset()) p.rawpiece = workpiece(expect(attr(wp, 3).as_reference(), {"WORKPIECE"}, wp));
    }
    const Instance& workplan = expect(reference(project, 1), {"WORKPLAN"}, project);
    p.main_workplan.its_id = text(workplan, 0);
    if (!attr(workplan, 3).is_unset()) p.setup = setup(expect(attr(workplan, 3).as_reference(), {"SETUP"}, workplan));
    for (const Value& v : list(workplan, 1)) executable(instance(reference_in(v, workplan), &workplan));
    return std::move(result_);
  }

 private:
  // ---- access with errors that name the instance
  [[noreturn]] void fail(const Instance& at, const std::string& message) const {
    throw InputError({file_, at.line, at.column}, "#" + std::to_string(at.id) + " " + at.entity() + ": " + message);
  }
  void warn(const Instance& at, std::string message) {
    Diagnostic d;
    d.severity = Severity::Warning;
    d.where = {file_, at.line, at.column};
    d.instance = at.id;
    d.entity = at.entity();
    d.message = std::move(message);
    result_.warnings.push_back(std::move(d));
  }
  // The instance `id`; a reference to one the file lacks is an error where the referring
  // instance (`from`) is.
  const Instance& instance(InstanceId id, const Instance* from = nullptr) const {
    const Instance* i = g_.find(id);
    if (!i || i->records.empty()) {
      const std::string message = "reference to #" + std::to_string(id) + ", which the file does not define";
      if (from) fail_complex(*from, message);
      throw InputError({file_, 1, 1}, message);
    }
    return *i;
  }
  const Value& attr(const Instance& i, std::size_t n) const {
    if (i.complex) fail(i, "complex instances are not part of an ISO 14649 program");
    if (n >= i.attributes().size()) fail(i, "has " + std::to_string(i.attributes().size()) + " attributes; attribute " + std::to_string(n + 1) + " is missing");
    return i.attributes()[n];
  }
  InstanceId reference_in(const Value& v, const Instance& at) const {
    if (!v.is_reference()) fail(at, "expected a reference");
    return v.as_reference();
  }
  InstanceId reference(const Instance& i, std::size_t n) const { return reference_in(attr(i, n), i); }
  std::string text(const Instance& i, std::size_t n) const {
    const Value& v = attr(i, n);
    if (v.is_unset()) return {};
    if (!v.is_string()) fail(i, "attribute " + std::to_string(n + 1) + " must be a string");
    return v.as_string();
  }
  double number(const Instance& i, std::size_t n) const {
    const Value& v = attr(i, n);
    if (!v.is_number() && !v.is_typed()) fail(i, "attribute " + std::to_string(n + 1) + " must be a number");
    return v.as_number();
  }
  std::optional<double> opt_number(const Instance& i, std::size_t n) const {
    if (n >= i.attributes().size() || attr(i, n).is_unset()) return std::nullopt;
    return number(i, n);
  }
  bool flag(const Instance& i, std::size_t n) const {
    const Value& v = attr(i, n);
    if (!v.is_enumeration()) fail(i, "attribute " + std::to_string(n + 1) + " must be .T. or .F.");
    return v.as_enumeration() == "T";
  }
  std::optional<bool> opt_flag(const Instance& i, std::size_t n) const {
    if (n >= i.attributes().size() || attr(i, n).is_unset()) return std::nullopt;
    return flag(i, n);
  }
  std::vector<Value> list(const Instance& i, std::size_t n) const {
    const Value& v = attr(i, n);
    if (v.is_unset()) return {};
    if (!v.is_list()) fail(i, "attribute " + std::to_string(n + 1) + " must be a list");
    return v.as_list();
  }
  const Instance& expect(InstanceId id, std::initializer_list<std::string_view> entities, const Instance& from) const {
    const Instance& i = instance(id, &from);
    for (auto e : entities) {
      if (!i.complex && i.entity() == e) return i;
    }
    std::string names;
    for (auto e : entities) names += (names.empty() ? "" : " or ") + std::string(e);
    fail(from, "refers to #" + std::to_string(id) + " " + (i.complex ? std::string("(complex)") : i.entity()) + ", expected " + names);
  }

  // ---- geometry
  sn::CartesianPoint point(const Instance& i) const {
    const auto c = list(i, 1);
    if (c.empty() || c.size() > 3) fail(i, "a point has 1 to 3 coordinates");
    sn::CartesianPoint p{0, 0, 0};
    p.x = c[0].as_number();
    if (c.size() > 1) p.y = c[1].as_number();
    if (c.size() > 2) p.z = c[2].as_number();
    return p;
  }
  sn::CartesianPoint point_ref(InstanceId id, const Instance& from) const { return point(expect(id, {"CARTESIAN_POINT"}, from)); }
  sn::Direction direction(InstanceId id, const Instance& from) const {
    const Instance& i = expect(id, {"DIRECTION"}, from);
    const auto c = list(i, 1);
    if (c.size() < 2) fail(i, "a direction has 2 or 3 ratios");
    return {c[0].as_number(), c[1].as_number(), c.size() > 2 ? c[2].as_number() : 0.0};
  }
  sn::Axis2Placement3d placement(InstanceId id, const Instance& from) const {
    const Instance& i = expect(id, {"AXIS2_PLACEMENT_3D"}, from);
    sn::Axis2Placement3d a;
    a.location = point_ref(reference(i, 1), i);
    if (!attr(i, 2).is_unset()) a.axis = direction(reference(i, 2), i);
    if (!attr(i, 3).is_unset()) a.ref_direction = direction(reference(i, 3), i);
    return a;
  }
  sn::Plane plane(InstanceId id, const Instance& from) const {
    const Instance& i = expect(id, {"PLANE"}, from);
    return {placement(reference(i, 1), i)};
  }
  sn::Polyline polyline(const Instance& i) const {
    sn::Polyline l;
    for (const Value& v : list(i, 1)) l.points.push_back(point_ref(reference_in(v, i), i));
    return l;
  }
  // A trim of a TRIMMED_CURVE: its point and its parameter, either of which may be missing
  // (NIST's files trim by points only).
  struct Trim {
    std::optional<sn::CartesianPoint> point;
    std::optional<double> parameter;
  };
  Trim trim(const Instance& i, std::size_t n) const {
    Trim t;
    for (const Value& v : list(i, n)) {
      if (v.is_reference()) t.point = point_ref(v.as_reference(), i);
      else t.parameter = v.as_number();
    }
    if (!t.point && !t.parameter) fail(i, "a trim needs a point or a PARAMETER_VALUE");
    return t;
  }
  // Local coordinates of a point in a placement: along ref_direction, axis x ref_direction, axis.
  static sn::CartesianPoint local(const sn::Axis2Placement3d& a, const sn::CartesianPoint& p) {
    const double dx = p.x - a.location.x, dy = p.y - a.location.y, dz = p.z - a.location.z;
    const sn::Direction& z = a.axis;
    const sn::Direction& x = a.ref_direction;
    const sn::Direction y{z.y * x.z - z.z * x.y, z.z * x.x - z.x * x.z, z.x * x.y - z.y * x.x};
    return {dx * x.x + dy * x.y + dz * x.z, dx * y.x + dy * y.y + dz * y.z, dx * z.x + dy * z.y + dz * z.z};
  }
  static sn::CartesianPoint global(const sn::Axis2Placement3d& a, double lx, double ly, double lz) {
    const sn::Direction& z = a.axis;
    const sn::Direction& x = a.ref_direction;
    const sn::Direction y{z.y * x.z - z.z * x.y, z.z * x.x - z.x * x.z, z.x * x.y - z.y * x.x};
    return {a.location.x + lx * x.x + ly * y.x + lz * z.x, a.location.y + lx * x.y + ly * y.y + lz * z.y,
            a.location.z + lx * x.z + ly * y.z + lz * z.z};
  }
  sn::TrimmedCircle trimmed_circle(const Instance& i, const Instance& circle) const {
    sn::TrimmedCircle t;
    t.position = placement(reference(circle, 1), circle);
    t.radius = number(circle, 2);
    auto resolve = [&](const Trim& tr, sn::CartesianPoint& pt, double& parameter) {
      constexpr double kDegrees = 180.0 / 3.14159265358979323846;
      if (tr.point) {
        pt = *tr.point;
        if (tr.parameter) {
          parameter = *tr.parameter;
        } else {
          const sn::CartesianPoint l = local(t.position, pt);
          parameter = std::atan2(l.y, l.x) * kDegrees;
          if (parameter < 0) parameter += 360.0;
        }
      } else {
        parameter = *tr.parameter;
        pt = global(t.position, t.radius * std::cos(parameter / kDegrees), t.radius * std::sin(parameter / kDegrees), 0);
      }
    };
    resolve(trim(i, 2), t.trim_1_point, t.trim_1_parameter);
    resolve(trim(i, 3), t.trim_2_point, t.trim_2_parameter);
    t.sense_agreement = flag(i, 4);
    return t;
  }
  // NIST's HELIX(name, position, radius, pitch) (not in the schema's Part 42 subset) trimmed by
  // two points: as a polyline within 0.001 mm of it, as the CC1 writer writes helices (docs/cc1.md).
  sn::Polyline trimmed_helix(const Instance& i, const Instance& helix) const {
    const sn::Axis2Placement3d a = placement(reference(helix, 1), helix);
    const double radius = number(helix, 2), pitch = number(helix, 3);
    const Trim t1 = trim(i, 2), t2 = trim(i, 3);
    if (!t1.point || !t2.point) fail(i, "a trimmed HELIX needs its trims as points");
    if (radius <= 0) fail(helix, "the radius must be positive");
    const sn::CartesianPoint s = local(a, *t1.point), e = local(a, *t2.point);
    constexpr double kPi = 3.14159265358979323846;
    const double a0 = std::atan2(s.y, s.x), a1 = std::atan2(e.y, e.x);
    const bool ccw = flag(i, 4);
    double sweep;
    if (pitch != 0 && std::fabs(e.z - s.z) > 1e-9) {
      sweep = (e.z - s.z) / pitch * 2 * kPi;  // signed: + counter-clockwise about the axis
      double miss = std::remainder(a0 + sweep - a1, 2 * kPi);
      if (std::fabs(miss) * radius > 0.01) fail(i, "the trim points are not on the helix");
      sweep -= miss;
    } else {
      sweep = ccw ? a1 - a0 : a0 - a1;
      while (sweep <= 1e-12) sweep += 2 * kPi;
      if (!ccw) sweep = -sweep;
    }
    constexpr double kChordTolerance = 0.001;  // mm
    const double step = 2 * std::acos(std::max(-1.0, 1 - kChordTolerance / radius));
    const double count = std::max(1.0, std::ceil(std::fabs(sweep) / step));
    if (!(count <= 1e6)) fail(i, "a helix of more than a million chords of 0.001 mm");
    const auto pieces = static_cast<std::size_t>(count);
    sn::Polyline l;
    l.points.push_back(*t1.point);
    for (std::size_t k = 1; k < pieces; ++k) {
      const double f = static_cast<double>(k) / static_cast<double>(pieces);
      const double angle = a0 + sweep * f;
      l.points.push_back(global(a, radius * std::cos(angle), radius * std::sin(angle), s.z + (e.z - s.z) * f));
    }
    l.points.push_back(*t2.point);
    return l;
  }
  // A TRIMMED_CURVE appended to a curve: an arc of a CIRCLE; the piece of a LINE between its
  // trims and a piece of a HELIX (both in NIST's explicit toolpaths) as polylines.
  void append_trimmed(const Instance& i, sn::CompositeCurve& c) const {
    const Instance& basis = expect(reference(i, 1), {"CIRCLE", "LINE", "HELIX"}, i);
    if (basis.entity() == "CIRCLE") {
      c.segments.emplace_back(trimmed_circle(i, basis));
    } else if (basis.entity() == "HELIX") {
      c.segments.emplace_back(trimmed_helix(i, basis));
    } else {
      const Trim t1 = trim(i, 2), t2 = trim(i, 3);
      auto on_line = [&](const Trim& t) {
        if (t.point) return *t.point;
        const sn::CartesianPoint origin = point_ref(reference(basis, 1), basis);
        const Instance& vector = expect(reference(basis, 2), {"VECTOR"}, basis);
        const sn::Direction d = direction(reference(vector, 1), vector);
        const double k = number(vector, 2) * *t.parameter;
        return sn::CartesianPoint{origin.x + d.x * k, origin.y + d.y * k, origin.z + d.z * k};
      };
      c.segments.emplace_back(sn::Polyline{{on_line(t1), on_line(t2)}});
    }
  }
  // B_SPLINE_CURVE_WITH_KNOTS, or the complex instance of it with RATIONAL_B_SPLINE_CURVE
  // (and attribute-less supertypes): the only complex instance an ISO 14649 toolpath holds.
  static bool is_bspline(const Instance& i) {
    if (!i.complex) return i.entity() == "B_SPLINE_CURVE_WITH_KNOTS";
    return i.record("B_SPLINE_CURVE") && i.record("B_SPLINE_CURVE_WITH_KNOTS") && i.record("RATIONAL_B_SPLINE_CURVE");
  }
  sn::BSplineCurve bspline(const Instance& i) const {
    // The attributes of B_SPLINE_CURVE, then those of B_SPLINE_CURVE_WITH_KNOTS, then the weights.
    std::vector<Value> a;
    if (!i.complex) {
      a = i.attributes();
    } else {
      static constexpr std::string_view kAllowed[] = {"BOUNDED_CURVE", "B_SPLINE_CURVE", "B_SPLINE_CURVE_WITH_KNOTS", "CURVE",
                                                      "GEOMETRIC_REPRESENTATION_ITEM", "RATIONAL_B_SPLINE_CURVE",
                                                      "REPRESENTATION_ITEM"};
      for (const auto& r : i.records) {
        if (std::find(std::begin(kAllowed), std::end(kAllowed), r.entity) == std::end(kAllowed)) {
          fail_complex(i, "a complex B-spline curve with a " + r.entity + " part");
        }
      }
      for (std::string_view part : {"B_SPLINE_CURVE", "B_SPLINE_CURVE_WITH_KNOTS", "RATIONAL_B_SPLINE_CURVE"}) {
        const auto& attributes = i.record(part)->attributes;
        a.insert(a.end(), attributes.begin(), attributes.end());
      }
    }
    if (a.size() != (i.complex ? 10u : 9u)) fail_complex(i, "a B-spline curve with " + std::to_string(a.size()) + " attributes");
    auto number_list = [&](const Value& v, const char* what) {
      if (!v.is_list()) fail_complex(i, std::string(what) + " must be a list");
      std::vector<double> out;
      for (const Value& x : v.as_list()) {
        if (!x.is_number()) fail_complex(i, std::string(what) + " must be numbers");
        out.push_back(x.as_number());
      }
      return out;
    };
    sn::BSplineCurve b;
    if (!a[1].is_integer()) fail_complex(i, "degree must be an integer");
    const auto degree = a[1].as_integer();
    if (degree < 1 || degree > 64) fail_complex(i, "degree " + std::to_string(degree) + " is not supported (1 to 64)");
    b.degree = static_cast<int>(degree);
    if (!a[2].is_list()) fail_complex(i, "control_points_list must be a list");
    for (const Value& v : a[2].as_list()) b.control_points.push_back(point_ref(reference_in(v, i), i));
    for (double m : number_list(a[6], "knot_multiplicities")) {
      if (m != std::floor(m) || m < 0 || m > 1e6) fail_complex(i, "knot_multiplicities must be small whole numbers");
      b.knot_multiplicities.push_back(static_cast<int>(m));
    }
    b.knots = number_list(a[7], "knots");
    if (!a[8].is_enumeration()) fail_complex(i, "knot_spec must be an enumeration");
    const std::string& spec = a[8].as_enumeration();
    b.knot_spec = spec == "UNIFORM_KNOTS" ? sn::KnotType::UniformKnots
                  : spec == "QUASI_UNIFORM_KNOTS" ? sn::KnotType::QuasiUniformKnots
                  : spec == "PIECEWISE_BEZIER_KNOTS" ? sn::KnotType::PiecewiseBezierKnots
                                                     : sn::KnotType::Unspecified;
    if (i.complex) b.weights = number_list(a[9], "weights_data");
    if (const std::string problem = sn::bspline_problem(b); !problem.empty()) fail_complex(i, "not a B-spline: " + problem);
    return b;
  }
  [[noreturn]] void fail_complex(const Instance& at, const std::string& message) const {
    throw InputError({file_, at.line, at.column},
                     "#" + std::to_string(at.id) + " " + (at.complex ? std::string("(complex)") : at.entity()) + ": " + message);
  }
  // A curve of a toolpath: a B-spline (NURBS) curve, a POLYLINE, a TRIMMED_CURVE, or a
  // COMPOSITE_CURVE of them.
  sn::CompositeCurve curve(InstanceId id, const Instance& from) const {
    const Instance& i = instance(id, &from);
    sn::CompositeCurve c;
    if (is_bspline(i)) {
      c.segments.emplace_back(bspline(i));
      return c;
    }
    expect(id, {"POLYLINE", "TRIMMED_CURVE", "B_SPLINE_CURVE_WITH_KNOTS", "COMPOSITE_CURVE"}, from);
    if (i.entity() == "POLYLINE") {
      c.segments.emplace_back(polyline(i));
    } else if (i.entity() == "TRIMMED_CURVE") {
      append_trimmed(i, c);
    } else {
      for (const Value& v : list(i, 1)) {
        const Instance& seg = expect(reference_in(v, i), {"COMPOSITE_CURVE_SEGMENT"}, i);
        if (!flag(seg, 1)) fail(seg, "a segment reversed (same_sense .F.) is not read");
        const InstanceId parent_id = reference(seg, 2);
        if (is_bspline(instance(parent_id))) {
          c.segments.emplace_back(bspline(instance(parent_id)));
          continue;
        }
        const Instance& parent = expect(parent_id, {"POLYLINE", "TRIMMED_CURVE", "B_SPLINE_CURVE_WITH_KNOTS"}, seg);
        if (parent.entity() == "POLYLINE") c.segments.emplace_back(polyline(parent));
        else append_trimmed(parent, c);
      }
    }
    return c;
  }

  // ---- resources
  sn::ToolRef tool(InstanceId id, const Instance& from) {
    if (auto it = tools_.find(id); it != tools_.end()) return it->second;
    const Instance& i = expect(id, {"MILLING_CUTTING_TOOL"}, from);
    sn::MillingCuttingTool t;
    t.its_id = text(i, 0);
    if (t.its_id.size() > 1 && t.its_id[0] == 'T' && std::isdigit(static_cast<unsigned char>(t.its_id[1]))) {
      t.number = std::atoi(t.its_id.c_str() + 1);
    }
    const Instance& body = instance(reference(i, 1), &i);
    static const std::map<std::string, sn::ToolBody, std::less<>> kBodies{
        {"FACEMILL", sn::ToolBody::Facemill}, {"ENDMILL", sn::ToolBody::Endmill},
        {"TAPERED_ENDMILL", sn::ToolBody::Endmill}, {"BALL_ENDMILL", sn::ToolBody::BallEndmill},
        {"BULLNOSE_ENDMILL", sn::ToolBody::BullnoseEndmill}, {"T_SLOT_MILL", sn::ToolBody::TSlotMill},
        {"TWIST_DRILL", sn::ToolBody::TwistDrill}, {"TAPERED_DRILL", sn::ToolBody::TwistDrill},
        {"CENTERDRILL", sn::ToolBody::Centerdrill}, {"COUNTERSINK", sn::ToolBody::Countersink},
        {"REAMER", sn::ToolBody::Reamer}, {"TAPERED_REAMER", sn::ToolBody::Reamer},
        {"TAP", sn::ToolBody::Tap}, {"TAPERED_TAP", sn::ToolBody::Tap},
        {"BORING_TOOL", sn::ToolBody::BoringTool}, {"USER_DEFINED_TOOL", sn::ToolBody::UserDefinedTool}};
    auto kind = kBodies.find(body.entity());
    if (kind == kBodies.end()) {
      warn(body, "tool body not mapped: read as USER_DEFINED_TOOL");
      t.body = sn::ToolBody::UserDefinedTool;
    } else {
      t.body = kind->second;
    }
    const Instance& dim = expect(reference(body, 0), {"MILLING_TOOL_DIMENSION"}, body);
    t.dimension.diameter = number(dim, 0);
    t.dimension.tool_tip_half_angle = opt_number(dim, 1);
    t.dimension.tool_circumference_angle = opt_number(dim, 2);
    t.dimension.cutting_edge_length = opt_number(dim, 3);
    t.dimension.edge_radius = opt_number(dim, 4);
    t.dimension.edge_center_vertical = opt_number(dim, 5);
    t.dimension.edge_center_horizontal = opt_number(dim, 6);
    if (!attr(body, 1).is_unset()) {
      if (!attr(body, 1).is_integer()) fail(body, "number_of_teeth must be an integer");
      t.number_of_teeth = attr(body, 1).as_integer();
    }
    if (!attr(body, 2).is_unset()) {
      if (!attr(body, 2).is_enumeration()) fail(body, "hand_of_cut must be .LEFT., .RIGHT. or .NEUTRAL.");
      const std::string& h = attr(body, 2).as_enumeration();
      t.hand_of_cut = h == "LEFT" ? sn::Hand::Left : h == "RIGHT" ? sn::Hand::Right : sn::Hand::Neutral;
    }
    t.coolant_through_tool = opt_flag(body, 3);
    t.pilot_length = opt_number(body, 4);
    const auto components = list(i, 2);
    if (!components.empty()) {
      const Instance& cc = expect(reference_in(components.front(), i), {"CUTTING_COMPONENT"}, i);
      t.tool_offset_length = number(cc, 0);
    }
    t.overall_assembly_length = opt_number(i, 3);
    result_.project.tools.push_back(std::move(t));
    const sn::ToolRef r{static_cast<std::uint32_t>(result_.project.tools.size() - 1)};
    tools_.emplace(id, r);
    return r;
  }
  sn::TechnologyRef technology(InstanceId id, const Instance& from) {
    if (auto it = technologies_.find(id); it != technologies_.end()) return it->second;
    const Instance& i = expect(id, {"MILLING_TECHNOLOGY"}, from);
    sn::MillingTechnology t;
    t.feedrate = opt_number(i, 0);
    t.feedrate_reference = attr(i, 1).is_enumeration() && attr(i, 1).as_enumeration() == "CCP" ? sn::ToolReferencePoint::Ccp
                                                                                                : sn::ToolReferencePoint::Tcp;
    t.cutspeed = opt_number(i, 2);
    t.spindle = opt_number(i, 3);
    t.feedrate_per_tooth = opt_number(i, 4);
    t.synchronize_spindle_with_feed = flag(i, 5);
    t.inhibit_feedrate_override = flag(i, 6);
    t.inhibit_spindle_override = flag(i, 7);
    result_.project.technologies.push_back(t);
    const sn::TechnologyRef r{static_cast<std::uint32_t>(result_.project.technologies.size() - 1)};
    technologies_.emplace(id, r);
    return r;
  }
  sn::MachineFunctionsRef functions(InstanceId id, const Instance& from) {
    if (auto it = functions_.find(id); it != functions_.end()) return it->second;
    const Instance& i = expect(id, {"MILLING_MACHINE_FUNCTIONS"}, from);
    sn::MillingMachineFunctions f;
    f.coolant = flag(i, 0);
    f.coolant_pressure = opt_number(i, 1);
    f.mist = opt_flag(i, 2);
    f.through_spindle_coolant = flag(i, 3);
    f.through_pressure = opt_number(i, 4);
    f.chip_removal = flag(i, 6);
    result_.project.machine_functions.push_back(f);
    const sn::MachineFunctionsRef r{static_cast<std::uint32_t>(result_.project.machine_functions.size() - 1)};
    functions_.emplace(id, r);
    return r;
  }

  sn::ToolpathList toolpath_list(InstanceId id, const Instance& from) {
    const Instance& i = expect(id, {"TOOLPATH_LIST"}, from);
    sn::ToolpathList l;
    for (const Value& v : list(i, 0)) {
      const Instance& t = expect(reference_in(v, i), {"CUTTER_LOCATION_TRAJECTORY"}, i);
      sn::CutterLocationTrajectory c;
      c.its_priority = flag(t, 0);
      static const std::map<std::string, sn::ToolpathType, std::less<>> kTypes{
          {"APPROACH", sn::ToolpathType::Approach}, {"LIFT", sn::ToolpathType::Lift},
          {"CONNECT", sn::ToolpathType::Connect}, {"NON_CONTACT", sn::ToolpathType::NonContact},
          {"CONTACT", sn::ToolpathType::Contact}, {"TRAJECTORY_PATH", sn::ToolpathType::TrajectoryPath}};
      const Value& type = attr(t, 1);
      auto k = type.is_enumeration() ? kTypes.find(type.as_enumeration()) : kTypes.end();
      if (k == kTypes.end()) fail(t, "its_type must be a toolpath_type");
      c.its_type = k->second;
      if (!attr(t, 3).is_unset()) c.its_technology = technology(reference(t, 3), t);
      if (!attr(t, 4).is_unset()) c.its_machine_functions = functions(reference(t, 4), t);
      c.its_direction = opt_flag(t, 5);
      c.basiccurve = curve(reference(t, 6), t);
      l.its_list.push_back(std::move(c));
    }
    return l;
  }

  // ---- operations
  void machining_operation(const Instance& i, sn::MachiningOperation& op) {
    if (!attr(i, 0).is_unset()) op.its_toolpath = toolpath_list(reference(i, 0), i);
    op.its_id = text(i, 2);
    op.retract_plane = opt_number(i, 3);
    if (!attr(i, 4).is_unset()) op.start_point = point_ref(reference(i, 4), i);
    op.its_tool = tool(reference(i, 5), i);
    op.its_technology = technology(reference(i, 6), i);
    op.its_machine_functions = functions(reference(i, 7), i);
    op.overcut_length = opt_number(i, 8);
  }
  void drilling(const Instance& i, sn::DrillingTypeOperation& op) {
    machining_operation(i, op);
    op.cutting_depth = opt_number(i, 9);
    op.previous_diameter = opt_number(i, 10);
    op.dwell_time_bottom = opt_number(i, 11);
    op.feed_on_retract = opt_number(i, 12);
    if (!attr(i, 13).is_unset()) {
      const Instance& s = expect(reference(i, 13), {"DRILLING_TYPE_STRATEGY"}, i);
      op.its_machining_strategy = sn::DrillingTypeStrategy{opt_number(s, 0), opt_number(s, 1), opt_number(s, 2),
                                                           opt_number(s, 3), opt_number(s, 4), opt_number(s, 5)};
    }
  }
  template <class Op>
  Op boring(const Instance& i) {
    Op op;
    drilling(i, op);
    op.spindle_stop_at_bottom = flag(i, 14);
    op.depth_of_testcut = opt_number(i, 15);
    if (!attr(i, 16).is_unset()) op.waiting_position = point_ref(reference(i, 16), i);
    return op;
  }
  template <class Op>
  Op simple_drilling(const Instance& i) {
    Op op;
    drilling(i, op);
    return op;
  }

  // 2.5D milling: MILLING_TYPE_OPERATION's approach and retract (not modelled), the strategy,
  // then the depths and allowances the subtype has.
  template <class Op>
  Op two5d(const Instance& i, bool plane, bool side) {
    Op op;
    machining_operation(i, op);
    if (!attr(i, 9).is_unset() || !attr(i, 10).is_unset()) warn(i, "approach/retract strategies are not kept");
    if (!attr(i, 11).is_unset()) op.its_machining_strategy = strategy(instance(reference(i, 11), &i));
    std::size_t n = 12;
    op.axial_cutting_depth = opt_number(i, n++);
    if (side) {
      op.radial_cutting_depth = opt_number(i, n++);
      op.allowance_side = opt_number(i, n++);
    }
    if (plane) op.allowance_bottom = opt_number(i, n++);
    return op;
  }
  std::optional<sn::Two5DMillingStrategy> strategy(const Instance& i) {
    const std::string& e = i.entity();
    auto cutmode = [&](std::size_t n) -> std::optional<sn::CutmodeType> {
      if (n >= i.attributes().size() || !attr(i, n).is_enumeration()) return std::nullopt;
      return attr(i, n).as_enumeration() == "CLIMB" ? sn::CutmodeType::Climb : sn::CutmodeType::Conventional;
    };
    auto rot = [&](std::size_t n) -> std::optional<sn::RotDirection> {
      if (n >= i.attributes().size() || !attr(i, n).is_enumeration()) return std::nullopt;
      return attr(i, n).as_enumeration() == "CW" ? sn::RotDirection::Cw : sn::RotDirection::Ccw;
    };
    auto dir = [&](std::size_t n) -> std::optional<sn::Direction> {
      if (n >= i.attributes().size() || attr(i, n).is_unset()) return std::nullopt;
      return direction(reference(i, n), i);
    };
    // TWO5D_MILLING_STRATEGY's overlap and allow_multiple_passes come first.
    const std::optional<double> overlap = i.attributes().empty() ? std::nullopt : opt_number(i, 0);
    const std::optional<bool> passes = i.attributes().size() < 2 ? std::nullopt : opt_flag(i, 1);
    if (e == "UNIDIRECTIONAL") return sn::Unidirectional{dir(2), cutmode(3), overlap, passes};
    if (e == "BIDIRECTIONAL" || e == "BIDIRECTIONAL_MILLING") {
      std::optional<sn::LeftOrRight> side;
      if (attr(i, 3).is_enumeration()) side = attr(i, 3).as_enumeration() == "LEFT" ? sn::LeftOrRight::Left : sn::LeftOrRight::Right;
      return sn::Bidirectional{dir(2), side, overlap, passes};
    }
    if (e == "CONTOUR_PARALLEL") return sn::ContourParallel{rot(2), cutmode(3), overlap, passes};
    if (e == "CONTOUR_SPIRAL") return sn::ContourSpiral{rot(2), cutmode(3), overlap, passes};
    if (e == "CENTER_MILLING") return sn::CenterMilling{overlap, passes};
    if (e == "BIDIRECTIONAL_CONTOUR" || e == "CONTOUR_BIDIRECTIONAL") {
      std::optional<sn::LeftOrRight> side;
      if (i.attributes().size() > 3 && attr(i, 3).is_enumeration()) {
        side = attr(i, 3).as_enumeration() == "LEFT" ? sn::LeftOrRight::Left : sn::LeftOrRight::Right;
      }
      if (e == "BIDIRECTIONAL_CONTOUR") return sn::BidirectionalContour{dir(2), side, rot(4), cutmode(5), overlap, passes};
      return sn::ContourBidirectional{dir(2), side, rot(4), cutmode(5), overlap, passes};
    }
    warn(i, "milling strategy " + e + " is not kept");
    return std::nullopt;
  }

  std::optional<sn::OperationRef> operation(InstanceId id, const Instance& from) {
    if (auto it = operations_.find(id); it != operations_.end()) return it->second;
    const Instance& i = instance(id, &from);
    const std::string& e = i.entity();
    sn::Operation op;
    if (e == "FREEFORM_OPERATION") {
      sn::FreeformOperation f;
      machining_operation(i, f);
      op = f;
    } else if (e == "DRILLING") {
      op = simple_drilling<sn::Drilling>(i);
    } else if (e == "CENTER_DRILLING") {
      op = simple_drilling<sn::CenterDrilling>(i);
    } else if (e == "BACK_BORING") {
      op = simple_drilling<sn::BackBoring>(i);
    } else if (e == "MULTISTEP_DRILLING") {
      sn::MultistepDrilling m;
      drilling(i, m);
      m.retract_distance = number(i, 14);
      m.first_depth = number(i, 15);
      m.depth_of_step = number(i, 16);
      m.dwell_time_step = opt_number(i, 17);
      op = m;
    } else if (e == "BORING") {
      op = boring<sn::Boring>(i);
    } else if (e == "REAMING") {
      op = boring<sn::Reaming>(i);
    } else if (e == "TAPPING") {
      sn::Tapping t;
      drilling(i, t);
      t.compensation_chuck = flag(i, 14);
      op = t;
    } else if (e == "PLANE_ROUGH_MILLING") {
      op = two5d<sn::PlaneRoughMilling>(i, true, false);
    } else if (e == "PLANE_FINISH_MILLING") {
      op = two5d<sn::PlaneFinishMilling>(i, true, false);
    } else if (e == "SIDE_ROUGH_MILLING") {
      op = two5d<sn::SideRoughMilling>(i, false, true);
    } else if (e == "SIDE_FINISH_MILLING") {
      op = two5d<sn::SideFinishMilling>(i, false, true);
    } else if (e == "BOTTOM_AND_SIDE_ROUGH_MILLING") {
      op = two5d<sn::BottomAndSideRoughMilling>(i, true, true);
    } else if (e == "BOTTOM_AND_SIDE_FINISH_MILLING") {
      op = two5d<sn::BottomAndSideFinishMilling>(i, true, true);
    } else {
      warn(i, "operation " + e + " is not read (not part of the model): its workingstep is left out");
      (void)from;
      return std::nullopt;
    }
    result_.project.operations.push_back(std::move(op));
    const sn::OperationRef r{static_cast<std::uint32_t>(result_.project.operations.size() - 1)};
    operations_.emplace(id, r);
    return r;
  }

  // ---- features
  sn::TolerancedLengthMeasure toleranced(InstanceId id, const Instance& from) {
    const Instance& d = expect(id, {"TOLERANCED_LENGTH_MEASURE"}, from);
    sn::TolerancedLengthMeasure t;
    t.theoretical_size = number(d, 0);
    const Instance& tol = instance(reference(d, 1), &d);
    if (tol.entity() == "PLUS_MINUS_VALUE") {
      t.upper_limit = number(tol, 0);
      t.lower_limit = number(tol, 1);
      if (!attr(tol, 2).is_integer()) fail(tol, "significant_digits must be an integer");
      t.significant_digits = static_cast<int>(attr(tol, 2).as_integer());
    } else {
      warn(tol, "tolerance kind not kept (read as +/-0)");
    }
    return t;
  }
  std::optional<sn::Axis2Placement3d> opt_placement(const Instance& i, std::size_t n) const {
    if (attr(i, n).is_unset()) return std::nullopt;
    return placement(reference(i, n), i);
  }
  sn::LinearPath linear_path(InstanceId id, const Instance& from) {
    const Instance& i = expect(id, {"LINEAR_PATH"}, from);
    return {opt_placement(i, 0), toleranced(reference(i, 1), i), direction(reference(i, 2), i)};
  }
  sn::LinearProfile linear_profile(const Instance& i) {
    const Instance& length = expect(reference(i, 1), {"NUMERIC_PARAMETER"}, i);
    return {opt_placement(i, 0), number(length, 1)};
  }
  sn::ClosedProfile closed_profile(InstanceId id, const Instance& from) {
    const Instance& i = expect(id, {"RECTANGULAR_CLOSED_PROFILE", "CIRCULAR_CLOSED_PROFILE", "GENERAL_CLOSED_PROFILE"}, from);
    if (i.entity() == "RECTANGULAR_CLOSED_PROFILE") {
      return sn::RectangularClosedProfile{opt_placement(i, 0), toleranced(reference(i, 1), i), toleranced(reference(i, 2), i)};
    }
    if (i.entity() == "CIRCULAR_CLOSED_PROFILE") return sn::CircularClosedProfile{opt_placement(i, 0), toleranced(reference(i, 1), i)};
    return sn::GeneralClosedProfile{opt_placement(i, 0), curve(reference(i, 1), i)};
  }
  sn::OpenProfile open_profile(InstanceId id, const Instance& from) {
    const Instance& i = expect(id, {"LINEAR_PROFILE", "GENERAL_PROFILE"}, from);
    if (i.entity() == "LINEAR_PROFILE") return linear_profile(i);
    return sn::GeneralProfile{opt_placement(i, 0), curve(reference(i, 1), i)};
  }
  template <class Pocket>
  void pocket(const Instance& i, Pocket& p) {
    if (!list(i, 5).empty()) warn(i, "bosses are not kept");
    p.slope = opt_number(i, 6);
    const Instance& bottom = instance(reference(i, 7), &i);
    if (bottom.entity() == "THROUGH_POCKET_BOTTOM_CONDITION") p.bottom_condition = sn::ThroughPocketBottomCondition{};
    else if (bottom.entity() == "PLANAR_POCKET_BOTTOM_CONDITION") p.bottom_condition = sn::PlanarPocketBottomCondition{};
    else warn(bottom, "pocket bottom " + bottom.entity() + " read as planar");
    if (!attr(i, 8).is_unset()) p.planar_radius = toleranced(reference(i, 8), i);
    if (!attr(i, 9).is_unset()) p.orthogonal_radius = toleranced(reference(i, 9), i);
  }

  std::optional<sn::FeatureRef> feature(InstanceId id, const Instance& from) {
    if (auto it = features_.find(id); it != features_.end()) return it->second;
    const Instance& i = instance(id, &from);
    auto common = [&](sn::MachiningFeature& f) {
      f.its_id = text(i, 0);
      f.feature_placement = placement(reference(i, 3), i);
      f.depth = plane(reference(i, 4), i);
    };
    sn::Feature feature;
    if (i.entity() == "TOOLPATH_FEATURE") {
      sn::ToolpathFeature t;
      common(t);
      feature = t;
    } else if (i.entity() == "ROUND_HOLE") {
      sn::RoundHole h;
      common(h);
      h.diameter = toleranced(reference(i, 5), i);
      const Instance& bottom = instance(reference(i, 7), &i);
      if (bottom.entity() == "THROUGH_BOTTOM_CONDITION") h.bottom_condition = sn::ThroughBottomCondition{};
      else if (bottom.entity() == "CONICAL_HOLE_BOTTOM") h.bottom_condition = sn::ConicalHoleBottom{number(bottom, 0)};
      else h.bottom_condition = sn::FlatHoleBottom{};
      feature = h;
    } else if (i.entity() == "PLANAR_FACE") {
      sn::PlanarFace p;
      common(p);
      p.course_of_travel = linear_path(reference(i, 5), i);
      p.removal_boundary = linear_profile(expect(reference(i, 6), {"LINEAR_PROFILE"}, i));
      if (!attr(i, 7).is_unset()) p.face_boundary = closed_profile(reference(i, 7), i);
      if (!list(i, 8).empty()) warn(i, "bosses are not kept");
      feature = p;
    } else if (i.entity() == "CLOSED_POCKET") {
      sn::ClosedPocket p;
      common(p);
      pocket(i, p);
      p.feature_boundary = closed_profile(reference(i, 10), i);
      feature = p;
    } else if (i.entity() == "OPEN_POCKET") {
      sn::OpenPocket p;
      common(p);
      pocket(i, p);
      p.open_boundary = open_profile(reference(i, 10), i);
      if (!attr(i, 11).is_unset()) p.wall_boundary = open_profile(reference(i, 11), i);
      feature = p;
    } else if (i.entity() == "SLOT") {
      sn::Slot s;
      common(s);
      s.course_of_travel = linear_path(reference(i, 5), i);
      s.swept_shape = open_profile(reference(i, 6), i);
      static const std::map<std::string, sn::SlotEndType, std::less<>> kEnds{
          {"OPEN_SLOT_END_TYPE", sn::SlotEndType::Open}, {"RADIUSED_SLOT_END_TYPE", sn::SlotEndType::Radiused},
          {"FLAT_SLOT_END_TYPE", sn::SlotEndType::Flat}, {"LOOP_SLOT_END_TYPE", sn::SlotEndType::Loop},
          {"WOODRUFF_SLOT_END_TYPE", sn::SlotEndType::Woodruff}};
      for (const Value& v : list(i, 7)) {
        const Instance& end = instance(reference_in(v, i), &i);
        auto k = kEnds.find(end.entity());
        if (k == kEnds.end()) fail(i, "refers to #" + std::to_string(end.id) + " " + end.entity() + ", expected a slot_end_type");
        s.end_conditions.push_back(k->second);
      }
      feature = s;
    } else if (i.entity() == "STEP") {
      sn::Step s;
      common(s);
      s.open_boundary = linear_path(reference(i, 5), i);
      if (!attr(i, 6).is_unset()) warn(i, "the step's wall boundary is not kept");
      feature = s;
    } else if (i.entity() == "GENERAL_OUTSIDE_PROFILE") {
      sn::GeneralOutsideProfile p;
      common(p);
      p.profile_swept_shape = linear_path(reference(i, 5), i);
      const Instance& boundary = expect(reference(i, 6), {"GENERAL_CLOSED_PROFILE", "GENERAL_PROFILE"}, i);
      p.closed = boundary.entity() == "GENERAL_CLOSED_PROFILE";
      p.feature_boundary = curve(reference(boundary, 1), boundary);
      feature = p;
    } else if (i.entity() == "REGION_PROJECTION") {
      sn::Region g;
      g.its_id = text(i, 0);
      if (!attr(i, 3).is_unset()) g.feature_placement = placement(reference(i, 3), i);
      g.proj_curve = curve(reference(i, 4), i);
      g.proj_dir = direction(reference(i, 5), i);
      g.depth = toleranced(reference(i, 6), i);
      feature = g;
    } else {
      warn(i, "feature " + i.entity() + " is not read (not part of the model): its workingsteps are left out");
      (void)from;
      return std::nullopt;
    }
    result_.project.features.push_back(std::move(feature));
    const sn::FeatureRef r{static_cast<std::uint32_t>(result_.project.features.size() - 1)};
    features_.emplace(id, r);
    return r;
  }

  // ---- workplan, workpiece, setup
  void executable(const Instance& i) {
    if (i.entity() == "MACHINING_WORKINGSTEP") {
      sn::MachiningWorkingstep ws;
      ws.its_id = text(i, 0);
      ws.its_secplane = plane(reference(i, 1), i);
      const auto f = feature(reference(i, 2), i);
      const auto o = operation(reference(i, 3), i);
      if (!f || !o) return;
      ws.its_feature = *f;
      ws.its_operation = *o;
      result_.project.main_workplan.its_elements.emplace_back(std::move(ws));
    } else if (i.entity() == "RAPID_MOVEMENT") {
      sn::RapidMovement r;
      r.its_id = text(i, 0);
      r.its_secplane = plane(reference(i, 1), i);
      if (!attr(i, 2).is_unset()) r.its_toolpath = toolpath_list(reference(i, 2), i);
      result_.project.main_workplan.its_elements.emplace_back(std::move(r));
    } else if (i.entity() == "WORKPIECE_PROBING") {
      sn::WorkpieceProbing w;
      w.its_id = text(i, 0);
      w.its_secplane = plane(reference(i, 1), i);
      if (!attr(i, 2).is_unset()) warn(i, "the toolpath of a workpiece probing is not kept");
      const Instance& variable = expect(reference(i, 4), {"NC_VARIABLE"}, i);
      w.measured_offset.its_name = text(variable, 0);
      w.measured_offset.initial_value = opt_number(variable, 1);
      w.start_position = placement(reference(i, 5), i);
      expect(reference(i, 6), {"WORKPIECE"}, i);  // the project's workpiece
      w.its_direction = direction(reference(i, 7), i);
      w.expected_value = toleranced(reference(i, 8), i);
      w.its_probe = text(expect(reference(i, 9), {"TOUCH_PROBE"}, i), 0);
      result_.project.main_workplan.its_elements.emplace_back(std::move(w));
    } else {
      warn(i, "executable " + i.entity() + " is not read (only workingsteps, rapid movements and workpiece probings)");
    }
  }

  sn::Workpiece workpiece(const Instance& i) {
    sn::Workpiece w;
    w.its_id = text(i, 0);
    w.global_tolerance = opt_number(i, 2);
    if (!attr(i, 5).is_unset()) {
      const Instance& b = instance(reference(i, 5), &i);
      if (b.entity() == "BLOCK") {
        w.its_bounding_geometry = sn::Block{placement(reference(b, 1), b), number(b, 2), number(b, 3), number(b, 4)};
      } else {
        warn(b, "bounding geometry " + b.entity() + " is not kept (only BLOCK)");
      }
    }
    for (const Value& v : list(i, 6)) w.clamping_positions.push_back(point_ref(reference_in(v, i), i));
    return w;
  }

  sn::Setup setup(const Instance& i) {
    sn::Setup s;
    s.its_id = text(i, 0);
    if (!attr(i, 1).is_unset()) s.its_origin = placement(reference(i, 1), i);
    s.its_secplane = plane(reference(i, 2), i);
    const auto wps = list(i, 3);
    if (!wps.empty()) {
      const Instance& wp = expect(reference_in(wps.front(), i), {"WORKPIECE_SETUP"}, i);
      s.its_workpiece_setup.its_origin = placement(reference(wp, 1), wp);
    }
    return s;
  }

  const Graph& g_;
  std::string file_;
  StepncReadResult result_;
  InstanceId workpiece_id_ = 0;
  std::map<InstanceId, sn::ToolRef> tools_;
  std::map<InstanceId, sn::TechnologyRef> technologies_;
  std::map<InstanceId, sn::MachineFunctionsRef> functions_;
  std::map<InstanceId, sn::OperationRef> operations_;
  std::map<InstanceId, sn::FeatureRef> features_;
};

}  // namespace

StepncReadResult stepnc_from_graph(const part21::Graph& graph, const std::string& file_name) {
  try {
    return Cc1Reader(graph, file_name).read();
  } catch (const std::logic_error& e) {
    // A value of the wrong kind where the reader did not check it first (part21::Value's
    // accessors): an input error of the file, never a crash.
    throw InputError({file_name, 1, 1}, std::string("an attribute of the wrong kind: ") + e.what());
  }
}

StepncReadResult read_stepnc(std::string_view text, const std::string& file_name) {
  auto r = part21::read_part21(text, file_name);
  auto result = stepnc_from_graph(r.graph, file_name);
  result.warnings.insert(result.warnings.begin(), r.warnings.begin(), r.warnings.end());
  return result;
}

StepncReadResult read_stepnc_file(const std::filesystem::path& path) {
  auto r = part21::read_part21_file(path);
  auto result = stepnc_from_graph(r.graph, path.string());
  result.warnings.insert(result.warnings.begin(), r.warnings.begin(), r.warnings.end());
  return result;
}

}  // namespace ncbridge::step_writer
