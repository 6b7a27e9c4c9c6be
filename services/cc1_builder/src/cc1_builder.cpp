// The canonical stream -> CC1 workingsteps. Segmentation (docs/cc1.md):
//   * consecutive feed moves with one tool, technology and machine functions form one
//     FREEFORM_OPERATION on a TOOLPATH_FEATURE, in one MACHINING_WORKINGSTEP;
//   * a run of rapids that retracts (moves up along Z), or that precedes the first cut, ends
//     the workingstep and becomes a RAPID_MOVEMENT; a run that stays down is kept in the
//     operation as a CONNECT trajectory between two cutting trajectories;
//   * a tool change or a change of feed, spindle speed/direction or coolant starts a new one;
//   * the calls of one canned-cycle hole become one drilling-family workingstep.
#include "ncbridge/cc1_builder/cc1_builder.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <map>
#include <unordered_map>
#include <utility>

#include "hole_cycle.hpp"
#include "machine_state.hpp"
#include "tool_mapping.hpp"
#include "toolpath_curve.hpp"

namespace ncbridge::cc1_builder {

namespace {

template <class... F> struct Overload : F... { using F::operator()...; };
template <class... F> Overload(F...) -> Overload<F...>;

constexpr double kRetractEpsilon = 1e-9;  // mm

void extend(stepnc::SourceLines& lines, const canonical::Source& source) {
  if (source.line == 0) return;
  if (lines.first_line == 0) {
    lines.file = source.file;
    lines.first_line = source.line;
  }
  lines.last_line = std::max(lines.last_line, source.line);
}

// "<prefix><n><suffix>", e.g. "WS12 FREEFORM7".
std::string numbered(std::string_view prefix, int n, std::string_view suffix = {}) {
  const std::string digits = std::to_string(n);
  std::string s;
  s.reserve(prefix.size() + digits.size() + suffix.size());
  s.append(prefix).append(digits).append(suffix);
  return s;
}

// The index of each distinct value of a table (technologies, machine functions), appending new
// ones: a hash lookup, as a program may set a new feed on every line.
template <class T, class RefT>
class Interned {
 public:
  RefT operator()(std::vector<T>& table, const T& value) {
    const std::uint64_t h = hash(value);
    auto [first, last] = index_.equal_range(h);
    for (auto it = first; it != last; ++it) {
      if (table[it->second] == value) return RefT{it->second};
    }
    table.push_back(value);
    const auto i = static_cast<std::uint32_t>(table.size() - 1);
    index_.emplace(h, i);
    return RefT{i};
  }

 private:
  static void mix(std::uint64_t& h, std::uint64_t w) {
    h ^= w;
    h *= 0xFF51AFD7ED558CCDull;
    h ^= h >> 32;
  }
  static void mix(std::uint64_t& h, const std::optional<double>& v) {
    mix(h, v ? std::bit_cast<std::uint64_t>(*v) : 0x7FF8DEADull);
  }
  static std::uint64_t hash(const stepnc::MillingTechnology& t) {
    std::uint64_t h = 0x9E3779B97F4A7C15ull;
    mix(h, t.feedrate);
    mix(h, t.cutspeed);
    mix(h, t.spindle);
    mix(h, t.feedrate_per_tooth);
    mix(h, static_cast<std::uint64_t>(t.feedrate_reference) | std::uint64_t{t.synchronize_spindle_with_feed} << 8 |
               std::uint64_t{t.inhibit_feedrate_override} << 9 | std::uint64_t{t.inhibit_spindle_override} << 10);
    return h;
  }
  static std::uint64_t hash(const stepnc::MillingMachineFunctions& f) {
    std::uint64_t h = 0x9E3779B97F4A7C15ull;
    mix(h, f.coolant_pressure);
    mix(h, f.through_pressure);
    mix(h, std::uint64_t{f.coolant} | std::uint64_t{f.through_spindle_coolant} << 1 | std::uint64_t{f.chip_removal} << 2 |
               (f.mist ? 8u + std::uint64_t{*f.mist} : 0u) << 3);
    return h;
  }

  std::unordered_multimap<std::uint64_t, std::uint32_t> index_;
};

}  // namespace

struct Cc1Builder::State {
  State(Options o, WorkplanSink* sink) : options(std::move(o)), elements(sink) {
    project.its_id = options.project_id;
    project.workpiece.its_id = "PART";
    if (options.stock) {
      stepnc::Workpiece raw;
      raw.its_id = "RAWPIECE";
      stepnc::Block block;
      block.position.location = {options.stock->min[0], options.stock->min[1], options.stock->min[2]};
      block.x = options.stock->size(0);
      block.y = options.stock->size(1);
      block.z = options.stock->size(2);
      raw.its_bounding_geometry = block;
      project.rawpiece = raw;
    }
  }

  struct OpenCut {
    int tool_number = 0;
    stepnc::MillingTechnology technology_value;
    stepnc::MillingMachineFunctions functions_value;
    stepnc::ToolRef tool;
    stepnc::TechnologyRef technology;
    stepnc::MachineFunctionsRef functions;
    std::vector<stepnc::CutterLocationTrajectory> trajectories;  // the last one is being cut
    double min_z = std::numeric_limits<double>::infinity();
    stepnc::SourceLines source;
  };
  struct PendingRapid {
    stepnc::Polyline path;
    bool retracts = false;
    double max_z = -std::numeric_limits<double>::infinity();
    stepnc::SourceLines source;
  };

  Options options;
  WorkplanSink* elements;  // streamed: finished elements go there, not into the project
  MachineState m;
  stepnc::Project project;
  std::vector<stepnc::Feature>& features = project.features;
  std::vector<stepnc::Operation>& operations = project.operations;
  std::vector<stepnc::Executable>& executables = project.main_workplan.its_elements;
  std::vector<Warning> warnings;
  std::vector<std::string> files;
  std::uint64_t calls = 0;
  bool ended = false;
  bool taken = false;

  std::map<int, stepnc::ToolRef> tool_refs;
  Interned<stepnc::MillingTechnology, stepnc::TechnologyRef> technologies;
  Interned<stepnc::MillingMachineFunctions, stepnc::MachineFunctionsRef> machine_functions;
  std::optional<OpenCut> cut;
  std::optional<PendingRapid> rapid;
  std::optional<HoleCycle> hole;
  std::uint32_t hole_cycle_id = 0;
  const setup::Tool* hole_tool = nullptr;

  int workingstep_count = 0, rapid_count = 0, freeform_count = 0, hole_count = 0, probing_count = 0;
  std::optional<double> max_rapid_z, max_motion_z;
  bool warned_unknown_start = false, warned_frame_shift = false, warned_inverse_time = false;
  bool warned_nurbs_plane = false;
  bool warned_rotation = false, warned_single_tool = false;
  bool frame_changed = false;

  // ---- diagnostics
  SourceLocation where(const canonical::Source& s) const {
    SourceLocation loc;
    if (s.file < files.size()) loc.file = files[s.file];
    loc.line = s.line;
    return loc;
  }
  void warn(const canonical::Source& s, std::string message) { warnings.push_back({where(s), std::move(message)}); }
  // An error names file:line:column: a canonical call knows its block, not a word in it, so the
  // block's first column (line 1 for a call the interpreter made before any block).
  SourceLocation error_at(const canonical::Source& s) const {
    SourceLocation loc = where(s);
    if (loc.line == 0) loc.line = 1;
    loc.column = 1;
    return loc;
  }

  // A warning a program may repeat on any number of lines: the first kRepeatedWarnings are
  // given, the rest counted and summed up at the end, so that warnings do not grow with the
  // program.
  static constexpr int kRepeatedWarnings = 10;
  struct Repeated {
    std::string_view message, rest;
    int count = 0;
    canonical::Source last;
  };
  Repeated probes_away{"probing away from the workpiece (G38.4, G38.5) has no ISO 14649 workingstep: left out of the workplan",
                      "more probing moves away from the workpiece (G38.4, G38.5) left out of the workplan"};
  Repeated probes_nowhere{"a probing move from an unknown position or without travel in X, Y or Z is left out of the workplan",
                          "more probing moves from an unknown position or without travel left out of the workplan"};
  Repeated rigid_taps{"rigid tapping (G33.1) outside a canned cycle is left out of the workplan",
                      "more rigid tapping moves (G33.1) left out of the workplan"};
  void warn_repeated(Repeated& r, const canonical::Source& s) {
    if (++r.count <= kRepeatedWarnings) {
      warn(s, std::string(r.message));
    } else {
      r.last = s;
    }
  }
  void sum_up(const Repeated& r) {
    if (r.count > kRepeatedWarnings) {
      warn(r.last, std::to_string(r.count - kRepeatedWarnings) + " " + std::string(r.rest) + " (the last here)");
    }
  }

  // ---- resources
  stepnc::ToolRef loaded_tool(const canonical::Source& s, const setup::Tool** info) {
    int number = m.tool;
    if (number == 0 && options.tools.tools().size() == 1) {
      number = options.tools.tools().front().number;
      if (!warned_single_tool) {
        warn(s, "cutting with no tool loaded: assuming T" + std::to_string(number) + ", the only tool in the tool list");
        warned_single_tool = true;
      }
    }
    const setup::Tool* tool = options.tools.find(number);
    if (tool == nullptr) {
      throw InputError(error_at(s), number == 0 ? "cutting motion with no tool loaded (no T.. M6 before it)"
                                             : "tool T" + std::to_string(number) + " is not in the tool list");
    }
    if (info) *info = tool;
    auto [it, inserted] = tool_refs.try_emplace(number);
    if (inserted) {
      project.tools.push_back(milling_cutting_tool(*tool));
      it->second = stepnc::ToolRef{static_cast<std::uint32_t>(project.tools.size() - 1)};
    }
    return it->second;
  }

  // ---- points
  stepnc::CartesianPoint point(const canonical::Call& c, const canonical::Pose& p) {
    if (frame_changed && m.setup_origin) {
      frame_changed = false;
      if (!warned_frame_shift && (m.frame_shift(0) != 0 || m.frame_shift(1) != 0 || m.frame_shift(2) != 0)) {
        warned_frame_shift = true;
        warn(c.source, "the work offset changed after the first motion: later points are converted into the first work offset's frame (the setup)");
      }
    }
    return m.to_setup(p.x, p.y, p.z);
  }
  void moved_to(const stepnc::CartesianPoint& p) {
    m.position = p;
    max_motion_z = std::max(max_motion_z.value_or(p.z), p.z);
  }

  // A finished element: kept in the project, or handed on with its feature and operation.
  void finished(stepnc::Executable e) {
    if (!elements) {
      executables.push_back(std::move(e));
      return;
    }
    elements->element(project, e);
    features.clear();
    operations.clear();
  }

  // ---- rapid runs
  void rapid_to(const canonical::Call& c, const stepnc::CartesianPoint& p) {
    max_rapid_z = std::max(max_rapid_z.value_or(p.z), p.z);
    if (!rapid) {
      rapid = PendingRapid{};  // not emplace(): clang 14 rejects it for a nested struct with member initialisers
      if (m.position) {
        rapid->path.points.push_back(*m.position);
        rapid->max_z = m.position->z;
      }
    }
    extend(rapid->source, c.source);
    if (!m.position || !(p == *m.position)) {
      if (m.position && p.z > m.position->z + kRetractEpsilon) rapid->retracts = true;
      rapid->path.points.push_back(p);
      rapid->max_z = std::max(rapid->max_z, p.z);
    }
    moved_to(p);
  }

  void flush_rapid() {
    if (!rapid) return;
    if (rapid->path.points.size() >= 2) {
      stepnc::RapidMovement r;
      r.its_id = numbered("RAPID", ++rapid_count);
      stepnc::CutterLocationTrajectory t;
      t.its_type = stepnc::ToolpathType::Connect;
      t.basiccurve.segments.emplace_back(std::move(rapid->path));
      r.its_toolpath = stepnc::ToolpathList{{std::move(t)}};
      r.source = rapid->source;
      finished(std::move(r));
    }
    rapid.reset();
  }

  // ---- cuts
  void close_cut() {
    if (!cut) return;
    // Feeds that did not move leave empty trajectories; a link with no cut after it goes too.
    auto& ts = cut->trajectories;
    ts.erase(std::remove_if(ts.begin(), ts.end(), [](const auto& t) { return t.basiccurve.segments.empty(); }), ts.end());
    while (!ts.empty() && ts.back().its_type == stepnc::ToolpathType::Connect) ts.pop_back();
    if (ts.empty()) {
      cut.reset();
      return;
    }
    stepnc::FreeformOperation op;
    const int n = ++freeform_count;
    op.its_id = numbered("FREEFORM", n, " ");
    op.its_id += project.tools[cut->tool.index].its_id;
    if (rapid && rapid->retracts) op.retract_plane = rapid->max_z;
    op.its_tool = cut->tool;
    op.its_technology = cut->technology;
    op.its_machine_functions = cut->functions;
    op.its_toolpath = stepnc::ToolpathList{std::move(cut->trajectories)};

    stepnc::ToolpathFeature feature;
    feature.its_id = numbered("TOOLPATH FEATURE", n);
    feature.depth.position.location.z = std::isfinite(cut->min_z) ? cut->min_z : 0.0;

    features.emplace_back(std::move(feature));
    operations.emplace_back(std::move(op));
    stepnc::MachiningWorkingstep ws;
    ws.its_id = numbered("WS", ++workingstep_count, " FREEFORM");
    ws.its_id += std::to_string(n);
    ws.its_feature = stepnc::FeatureRef{static_cast<std::uint32_t>(features.size() - 1)};
    ws.its_operation = stepnc::OperationRef{static_cast<std::uint32_t>(operations.size() - 1)};
    ws.source = cut->source;
    finished(std::move(ws));
    cut.reset();
  }

  stepnc::CutterLocationTrajectory cutting_trajectory() const {
    stepnc::CutterLocationTrajectory t;
    t.its_type = stepnc::ToolpathType::TrajectoryPath;
    t.its_technology = cut->technology;
    return t;
  }

  // Makes sure a cut with the current tool and technology is open; returns false when the
  // start of the move is unknown (the first motion of the program is a feed).
  bool prepare_feed(const canonical::Call& c) {
    finish_hole();
    if (!m.position) {
      if (!warned_unknown_start) {
        warn(c.source, "the program's first motion is a feed from an unknown position: it starts the toolpath at its end point");
        warned_unknown_start = true;
      }
      return false;
    }
    if (m.feed_mode == 1 && !warned_inverse_time) {
      warn(c.source, "inverse time feed (G93): MILLING_TECHNOLOGY.feedrate holds the F number, not a speed");
      warned_inverse_time = true;
    }
    const auto technology = m.technology();
    const auto functions = m.machine_functions();
    const bool same = cut && cut->tool_number == m.tool && cut->technology_value == technology &&
                      cut->functions_value == functions && !(rapid && rapid->retracts);
    if (same) {
      if (rapid) {  // a link that stays down: kept inside the operation
        if (rapid->path.points.size() >= 2) {
          stepnc::CutterLocationTrajectory link;
          link.its_type = stepnc::ToolpathType::Connect;
          link.basiccurve.segments.emplace_back(std::move(rapid->path));
          cut->trajectories.push_back(std::move(link));
          cut->trajectories.push_back(cutting_trajectory());
        }
        extend(cut->source, c.source);
        rapid.reset();
      }
    } else {
      close_cut();
      flush_rapid();
      cut = OpenCut{};
      cut->tool_number = m.tool;
      cut->tool = loaded_tool(c.source, nullptr);
      cut->technology_value = technology;
      cut->functions_value = functions;
      cut->technology = technologies(project.technologies, technology);
      cut->functions = machine_functions(project.machine_functions, functions);
      cut->trajectories.push_back(cutting_trajectory());
    }
    extend(cut->source, c.source);
    cut->min_z = std::min(cut->min_z, m.position->z);
    return true;
  }

  void straight_feed(const canonical::Call& c, const canonical::StraightFeed& f) {
    const auto p = point(c, f.end);
    if (prepare_feed(c)) {
      append_line(cut->trajectories.back().basiccurve, *m.position, p);
      cut->min_z = std::min(cut->min_z, p.z);
    }
    moved_to(p);
  }

  void arc_feed(const canonical::Call& c, const canonical::ArcFeed& a) {
    const PlaneAxes axes = axes_of(m.plane);
    stepnc::CartesianPoint end;
    set(end, axes.first, m.axis_to_setup(axes.first, a.first_end));
    set(end, axes.second, m.axis_to_setup(axes.second, a.second_end));
    set(end, axes.normal, m.axis_to_setup(axes.normal, a.axis_end_point));
    const double centre_first = m.axis_to_setup(axes.first, a.first_axis);
    const double centre_second = m.axis_to_setup(axes.second, a.second_axis);
    if (prepare_feed(c)) {
      auto& curve = cut->trajectories.back().basiccurve;
      const std::size_t before = curve.segments.size();
      append_arc(curve, *m.position, end, centre_first, centre_second, axes, a.rotation,
                 options.helix_chord_tolerance);
      for (std::size_t i = before == 0 ? 0 : before - 1; i < curve.segments.size(); ++i) {
        std::visit(Overload{[&](const stepnc::Polyline& l) {
                              for (const auto& q : l.points) cut->min_z = std::min(cut->min_z, q.z);
                            },
                            [&](const stepnc::TrimmedCircle& t) { cut->min_z = std::min(cut->min_z, lowest_z(t)); },
                            [&](const stepnc::BSplineCurve&) {}},
                   curve.segments[i]);
      }
    }
    moved_to(end);
  }

  // A NURBS in the XY plane at the current height (G5, G5.1, G5.2/G5.3): one B-spline segment.
  void nurbs_feed(const canonical::Call& c, const canonical::NurbsFeed& f) {
    if (f.control_points.empty()) throw InputError(error_at(c.source), "NURBS_FEED without control points");
    const double z = m.position ? m.position->z : 0.0;
    std::vector<stepnc::CartesianPoint> points;
    std::vector<double> weights;
    points.reserve(f.control_points.size());
    for (const auto& q : f.control_points) {
      points.push_back({m.axis_to_setup(0, q.x), m.axis_to_setup(1, q.y), z});
      weights.push_back(q.weight);
    }
    stepnc::BSplineCurve spline;
    try {
      spline = nurbs_curve(points, weights, f.order);
    } catch (const std::invalid_argument& e) {
      throw InputError(error_at(c.source), e.what());
    }
    if (m.plane != canonical::Plane::XY && !warned_nurbs_plane) {
      warn(c.source, "a NURBS (G5, G5.1, G5.2) outside the XY plane: its control points are taken in XY, as LinuxCNC does");
      warned_nurbs_plane = true;
    }
    const stepnc::CartesianPoint end = points.back();
    if (prepare_feed(c)) {
      auto& curve = cut->trajectories.back().basiccurve;
      if (!(points.front() == *m.position)) append_line(curve, *m.position, points.front());
      append_bspline(curve, std::move(spline));
    }
    moved_to(end);
  }

  // ---- probing
  // G38.2/G38.3 (towards the workpiece until the probe touches): a WORKPIECE_PROBING of its own,
  // from where the move starts along its direction; contact is expected anywhere up to the
  // programmed end point, i.e. at half the travel +/- half the travel. The result goes to
  // LinuxCNC's probe parameters. G38.4/G38.5 (away until contact is lost) have no ISO 14649
  // counterpart: left out, with a warning.
  void probe(const canonical::Call& c, const canonical::StraightProbe& p) {
    break_all();
    const stepnc::CartesianPoint end = point(c, p.end);
    if ((p.probe_type & 2) != 0) {
      warn_repeated(probes_away, c.source);
      moved_to(end);
      return;
    }
    const double dx = m.position ? end.x - m.position->x : 0.0;
    const double dy = m.position ? end.y - m.position->y : 0.0;
    const double dz = m.position ? end.z - m.position->z : 0.0;
    const double travel = std::sqrt(dx * dx + dy * dy + dz * dz);
    if (!m.position || !(travel > 0) || !std::isfinite(travel)) {
      warn_repeated(probes_nowhere, c.source);
      moved_to(end);
      return;
    }
    stepnc::WorkpieceProbing w;
    w.its_id = numbered("PROBING", ++probing_count);
    w.start_position.location = *m.position;
    w.its_direction = {dx / travel, dy / travel, dz / travel};
    w.expected_value.theoretical_size = travel / 2;
    w.expected_value.upper_limit = travel / 2;
    w.expected_value.lower_limit = travel / 2;
    const bool x_only = dy == 0 && dz == 0, y_only = dx == 0 && dz == 0, z_only = dx == 0 && dy == 0;
    w.measured_offset.its_name = x_only ? "#5061" : y_only ? "#5062" : z_only ? "#5063" : "#5061..#5063";
    w.its_probe = m.tool != 0 ? "T" + std::to_string(m.tool) : "PROBE";
    extend(w.source, c.source);
    finished(std::move(w));
    moved_to(end);
  }

  // ---- canned cycles
  void cycle_call(const canonical::Call& c) {
    const canonical::CycleTag& tag = *c.cycle;
    if (hole && hole_cycle_id != tag.cycle_id) finish_hole();
    if (!hole) {
      close_cut();
      flush_rapid();
      hole = HoleCycle{};
      hole_cycle_id = tag.cycle_id;
      const canonical::Plane plane = tag.plane == 1 ? canonical::Plane::YZ
                                     : tag.plane == 2 ? canonical::Plane::XZ : canonical::Plane::XY;
      const PlaneAxes axes = axes_of(plane);
      hole->g_code_x10 = tag.g_code_x10;
      hole->first_axis = axes.first;
      hole->second_axis = axes.second;
      hole->normal_axis = axes.normal;
      hole->first = m.axis_to_setup(axes.first, tag.x);
      hole->second = m.axis_to_setup(axes.second, tag.y);
      hole->r = m.axis_to_setup(axes.normal, tag.r);
      hole->bottom = m.axis_to_setup(axes.normal, tag.z);
      hole->q = tag.q * m.to_mm;
      hole->p = tag.p;
      hole->tool = loaded_tool(c.source, &hole_tool);
      hole->technology = technologies(project.technologies, m.technology());
      hole->machine_functions =
          machine_functions(project.machine_functions, m.machine_functions());
    }
    extend(hole->source, c.source);
    auto follow = [&](const stepnc::CartesianPoint& p, bool feed) {
      if (m.position) hole->observe(feed, get(*m.position, hole->normal_axis), get(p, hole->normal_axis));
      if (!feed) max_rapid_z = std::max(max_rapid_z.value_or(p.z), p.z);
      moved_to(p);
    };
    std::visit(Overload{[&](const canonical::StraightTraverse& t) { follow(point(c, t.end), false); },
                        [&](const canonical::StraightFeed& f) { follow(point(c, f.end), true); },
                        [&](const auto&) {}},
               c.data);
  }

  void finish_hole() {
    if (!hole) return;
    const int n = ++hole_count;
    HoleResult r = make_hole(*hole, *hole_tool, options.stock, options.hole_diameter_tolerance, n);
    const std::string op_id = stepnc::machining_operation(r.operation).its_id;
    features.emplace_back(std::move(r.feature));
    operations.emplace_back(std::move(r.operation));
    stepnc::MachiningWorkingstep ws;
    ws.its_id = numbered("WS", ++workingstep_count, " ");
    ws.its_id += op_id;
    ws.its_feature = stepnc::FeatureRef{static_cast<std::uint32_t>(features.size() - 1)};
    ws.its_operation = stepnc::OperationRef{static_cast<std::uint32_t>(operations.size() - 1)};
    ws.source = hole->source;
    finished(std::move(ws));
    hole.reset();
  }

  void break_all() {
    finish_hole();
    close_cut();
    flush_rapid();
  }

  // ---- the stream
  void handle(const canonical::Call& c) {
    ++calls;
    // Motions of a canned cycle belong to its hole; its other calls (feed, spindle reversal,
    // dwell) only change the modal state.
    if (c.cycle && (std::holds_alternative<canonical::StraightTraverse>(c.data) ||
                    std::holds_alternative<canonical::StraightFeed>(c.data))) {
      cycle_call(c);
      return;
    }
    std::visit(
        Overload{
            [&](const canonical::UseLengthUnits& u) { m.to_mm = u.units == canonical::Units::Inches ? 25.4 : 1.0; },
            [&](const canonical::SetG5xOffset& o) {
              m.g5x = {o.offset.x * m.to_mm, o.offset.y * m.to_mm, o.offset.z * m.to_mm};
              frame_changed = true;
            },
            [&](const canonical::SetG92Offset& o) {
              m.g92 = {o.offset.x * m.to_mm, o.offset.y * m.to_mm, o.offset.z * m.to_mm};
              frame_changed = true;
            },
            [&](const canonical::SetXyRotation& r) {
              if (r.degrees != 0 && !warned_rotation) {
                warn(c.source, "XY rotation of the coordinate system (G10 L2 R) is not applied to the toolpaths");
                warned_rotation = true;
              }
            },
            [&](const canonical::SelectPlane& p) { m.plane = p.plane; },
            [&](const canonical::StraightTraverse& t) {
              finish_hole();
              rapid_to(c, point(c, t.end));
            },
            [&](const canonical::SetFeedRate& f) { m.feed = f.rate * m.to_mm; },
            [&](const canonical::SetFeedMode& f) { m.feed_mode = f.mode; },
            [&](const canonical::StraightFeed& f) { straight_feed(c, f); },
            [&](const canonical::ArcFeed& a) { arc_feed(c, a); },
            [&](const canonical::NurbsFeed& f) { nurbs_feed(c, f); },
            [&](const canonical::StraightProbe& p) { probe(c, p); },
            [&](const canonical::RigidTap&) {
              break_all();
              warn_repeated(rigid_taps, c.source);
            },
            [&](const canonical::SetSpindleSpeed& s) { m.spindle_rpm = s.rpm; },
            [&](const canonical::StartSpindleClockwise&) { m.spindle = canonical::Direction::Clockwise; },
            [&](const canonical::StartSpindleCounterclockwise&) { m.spindle = canonical::Direction::Counterclockwise; },
            [&](const canonical::StopSpindleTurning&) { m.spindle = canonical::Direction::Stopped; },
            [&](const canonical::SelectTool& t) { m.selected_tool = t.tool; },
            [&](const canonical::ChangeTool& t) {
              break_all();
              m.tool = m.selected_tool != 0 ? m.selected_tool : t.slot;
            },
            [&](const canonical::ChangeToolNumber& t) {
              break_all();
              m.tool = t.number;
            },
            [&](const canonical::FloodOn&) { m.flood = true; },
            [&](const canonical::FloodOff&) { m.flood = false; },
            [&](const canonical::MistOn&) { m.mist = true; },
            [&](const canonical::MistOff&) { m.mist = false; },
            [&](const canonical::ProgramEnd&) { break_all(); },
            [&](const canonical::ProgramStop&) { break_all(); },
            [&](const canonical::PalletShuttle&) { break_all(); },
            [&](const auto&) {}},
        c.data);
  }

  void finish() {
    break_all();
    sum_up(probes_away);
    sum_up(probes_nowhere);
    sum_up(rigid_taps);
    const double secplane_z = options.security_plane_z.value_or(max_rapid_z.value_or(max_motion_z.value_or(0.0)));
    stepnc::Plane secplane;
    secplane.position.location.z = secplane_z;
    for (auto& e : executables) std::visit([&](auto& x) { x.its_secplane = secplane; }, e);
    project.setup.its_secplane = secplane;
    if (m.setup_origin) {
      stepnc::Axis2Placement3d origin;
      origin.location = {(*m.setup_origin)[0], (*m.setup_origin)[1], (*m.setup_origin)[2]};
      project.setup.its_origin = origin;
    }
  }
};

Cc1Builder::Cc1Builder(Options options, WorkplanSink* elements)
    : state_(std::make_unique<State>(std::move(options), elements)) {}
Cc1Builder::~Cc1Builder() = default;

void Cc1Builder::source_file(std::uint32_t index, std::string_view path) {
  if (state_->files.size() <= index) state_->files.resize(index + 1);
  state_->files[index] = std::string(path);
}

void Cc1Builder::call(const canonical::Call& call) {
  if (state_->ended) throw std::logic_error("cc1_builder: call after end()");
  state_->handle(call);
}

void Cc1Builder::end() {
  if (state_->ended) return;
  state_->finish();
  state_->ended = true;
}

stepnc::Project Cc1Builder::take_project() {
  if (!state_->ended) throw std::logic_error("cc1_builder: take_project() before end()");
  if (state_->taken) throw std::logic_error("cc1_builder: take_project() called twice");
  state_->taken = true;
  return std::move(state_->project);
}

const std::vector<Warning>& Cc1Builder::warnings() const { return state_->warnings; }
std::uint64_t Cc1Builder::calls_seen() const { return state_->calls; }

stepnc::Project build_cc1(const std::vector<canonical::Call>& calls, Options options, std::vector<Warning>* warnings) {
  Cc1Builder builder(std::move(options));
  for (const auto& c : calls) builder.call(c);
  builder.end();
  if (warnings) *warnings = builder.warnings();
  return builder.take_project();
}

}  // namespace ncbridge::cc1_builder
