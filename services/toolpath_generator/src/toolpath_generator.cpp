#include "ncbridge/toolpath_generator/toolpath_generator.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <set>
#include <type_traits>

#include "cc1_toolpath.hpp"
#include "milling.hpp"
#include "ncbridge/common/error.hpp"
#include "ncbridge/material_check/cutter_shape.hpp"
#include "ncbridge/material_check/feature_region.hpp"

namespace ncbridge::toolpath_generator {

namespace {

namespace sn = stepnc;
namespace mc = material_check;

const sn::DrillingTypeOperation* as_drilling(const sn::Operation& op) {
  return std::visit(
      [](const auto& o) -> const sn::DrillingTypeOperation* {
        if constexpr (std::is_base_of_v<sn::DrillingTypeOperation, std::decay_t<decltype(o)>>) return &o;
        else return nullptr;
      },
      op);
}

sn::DrillingTypeOperation* as_drilling(sn::Operation& op) {
  return const_cast<sn::DrillingTypeOperation*>(as_drilling(static_cast<const sn::Operation&>(op)));
}

bool is_milling(const sn::Operation& op) {
  return std::visit([](const auto& o) { return std::is_base_of_v<sn::Two5DMillingOperation, std::decay_t<decltype(o)>>; }, op);
}

void check_options(const Options& o) {
  auto bad = [&](const std::string& what) { throw InputError({o.source_name, 0, 0}, "toolpath options: " + what); };
  if (!(o.clearance > 0)) bad("the clearance must be positive");
  if (!(o.stepover_ratio > 0 && o.stepover_ratio <= 1)) bad("the stepover ratio must be in (0, 1]");
  if (!(o.axial_depth_ratio > 0)) bad("the axial depth ratio must be positive");
  if (!(o.run_out > 0)) bad("the run-out must be positive");
  if (!(o.ramp_angle_deg > 0 && o.ramp_angle_deg < 90)) bad("the ramp angle must be between 0 and 90 degrees");
  if (!(o.entry_feed_ratio > 0 && o.entry_feed_ratio <= 1)) bad("the entry feed ratio must be in (0, 1]");
  if (!(o.breakthrough >= 0)) bad("the breakthrough must not be negative");
}

// The stock: the rawpiece's block, the options', or the features' extent.
setup::Stock stock_of(const sn::Project& cc2, const std::vector<std::size_t>& used, const Options& o,
                      std::vector<std::string>& warnings, const std::function<std::string(std::size_t)>& step_of) {
  if (cc2.rawpiece && cc2.rawpiece->its_bounding_geometry) {
    const auto& b = *cc2.rawpiece->its_bounding_geometry;
    const auto& p = b.position.location;
    setup::Stock s;
    s.min = {p.x, p.y, p.z};
    s.max = {p.x + b.x, p.y + b.y, p.z + b.z};
    return s;
  }
  if (o.stock) return *o.stock;
  // The features' extent (steps and outside profiles by their walls only: they run to the
  // stock's edge, which is what is sought).
  setup::Stock huge;
  huge.min = {-1e5, -1e5, -1e5};
  huge.max = {1e5, 1e5, 1e5};
  setup::Stock s;
  s.min = {1e300, 1e300, 1e300};
  s.max = {-1e300, -1e300, -1e300};
  for (auto index : used) {
    const auto& f = cc2.features[index];
    mc::FeatureRegion r;
    try {
      r = mc::feature_region(f, index, huge, o.source_name);
    } catch (const InputError& e) {
      throw InputError(e.where(), e.message() + " (machined by workingstep '" + step_of(index) + "')");
    }
    std::vector<mc::PlanarCurve> curves = r.outline;
    if (std::holds_alternative<sn::GeneralOutsideProfile>(f)) curves = {r.outline.back()};
    if (std::holds_alternative<sn::Step>(f)) {
      const auto& c = r.outline.front();
      curves = {mc::PlanarCurve{{c.segments.front()}, false}};
    }
    for (const auto& c : curves) {
      for (const auto& p : c.points(0.01)) {
        s.min[0] = std::min(s.min[0], p.x), s.min[1] = std::min(s.min[1], p.y);
        s.max[0] = std::max(s.max[0], p.x), s.max[1] = std::max(s.max[1], p.y);
      }
    }
    s.max[2] = std::max(s.max[2], r.top_z);
    s.min[2] = std::min(s.min[2], r.top_z - r.depth);
  }
  if (!(s.min[0] < s.max[0] && s.min[1] < s.max[1] && s.min[2] < s.max[2])) {
    throw InputError({o.source_name, 0, 0}, "the model has no rawpiece and its features give no extent: give a stock");
  }
  warnings.push_back("the model has no rawpiece: the stock is taken as the features' extent, (" + std::to_string(s.min[0]) + ", " +
                     std::to_string(s.min[1]) + ", " + std::to_string(s.min[2]) + ") to (" + std::to_string(s.max[0]) + ", " +
                     std::to_string(s.max[1]) + ", " + std::to_string(s.max[2]) + ")");
  return s;
}

// A band `width` wide on the outer side of a feature's open edges (away from its area): where
// the cutter runs out past them.
PolygonSet open_side(const std::vector<mc::PlanarCurve>& edges, const PolygonSet& area, double width) {
  PolygonSet out;
  for (const auto& e : edges) {
    if (e.closed) {
      mc::PlanarCurve ccw = e.signed_area() < 0 ? e.reversed() : e;
      const PolygonSet inside = PolygonSet::from_curves({ccw}, kArcTolerance);
      out = out.united(inside.offset(width, kArcTolerance).minus(inside));
      continue;
    }
    const auto pts = e.points(kArcTolerance);
    std::vector<PolygonSet::Ring> quads;
    for (std::size_t k = 1; k < pts.size(); ++k) {
      const mc::Point2 a = pts[k - 1], b = pts[k];
      const double len = distance(a, b);
      if (len < 1e-9) continue;
      mc::Point2 n{-(b.y - a.y) / len, (b.x - a.x) / len};
      const mc::Point2 mid{(a.x + b.x) / 2 + n.x * 0.01, (a.y + b.y) / 2 + n.y * 0.01};
      if (area.contains(mid)) n = {-n.x, -n.y};
      quads.push_back({a, b, {b.x + n.x * width, b.y + n.y * width}, {a.x + n.x * width, a.y + n.y * width}});
    }
    out = out.united(PolygonSet::from_rings(std::move(quads)));
  }
  return out.minus(area);
}

class Generator {
 public:
  Generator(const sn::Project& cc2, const Options& o) : cc2_(cc2), o_(o) {}

  GeneratedToolpaths run() {
    check_options(o_);
    std::vector<const sn::MachiningWorkingstep*> steps;
    std::set<std::size_t> used;
    std::map<std::size_t, double> largest_radius;
    for (const auto& e : cc2_.main_workplan.its_elements) {
      if (const auto* ws = std::get_if<sn::MachiningWorkingstep>(&e)) {
        steps.push_back(ws);
        check_refs(*ws);
        const auto& f = cc2_.feature(ws->its_feature);
        if (std::holds_alternative<sn::ToolpathFeature>(f)) continue;
        const auto& op = cc2_.operation(ws->its_operation);
        if (std::holds_alternative<sn::FreeformOperation>(op)) continue;
        used.insert(ws->its_feature.index);
        const double d = cc2_.tool(sn::machining_operation(op).its_tool).dimension.diameter;
        largest_radius[ws->its_feature.index] = std::max(largest_radius[ws->its_feature.index], d / 2);
      }
    }
    const setup::Stock stock =
        stock_of(cc2_, {used.begin(), used.end()}, o_, out_.warnings, [this](std::size_t f) { return first_step_of(f); });
    std::vector<ShapedFeature> shaped;
    for (auto index : used) {
      ShapedFeature s;
      try {
        s.region = mc::feature_region(cc2_.features[index], index, stock, o_.source_name);
      } catch (const InputError& e) {
        throw InputError(e.where(), e.message() + " (machined by workingstep '" + first_step_of(index) + "')");
      }
      s.cc2 = &cc2_.features[index];
      s.area = PolygonSet::from_curves(s.region.outline, kArcTolerance);
      if (s.area.empty()) throw InputError({o_.source_name, 0, 0}, "feature '" + s.region.id + "' encloses no area");
      if (!s.region.open_edges.empty()) {
        s.open_side = open_side(s.region.open_edges, s.area, 2 * largest_radius[index] + o_.run_out + 2);
      }
      s.box = s.area.box();
      shaped.push_back(std::move(s));
    }
    PartModel part(stock, std::move(shaped));
    part_ = &part;

    auto& p = out_.cc1;
    p.its_id = cc2_.its_id;
    p.main_workplan.its_id = cc2_.main_workplan.its_id;
    p.workpiece = cc2_.workpiece;
    p.rawpiece = cc2_.rawpiece;
    if (!p.rawpiece || !p.rawpiece->its_bounding_geometry) {
      sn::Workpiece raw;
      raw.its_id = "RAWPIECE";
      sn::Block b;
      b.position.location = {stock.min[0], stock.min[1], stock.min[2]};
      b.x = stock.size(0), b.y = stock.size(1), b.z = stock.size(2);
      raw.its_bounding_geometry = b;
      p.rawpiece = raw;
    }
    p.setup = cc2_.setup;
    p.tools = cc2_.tools;
    p.technologies = cc2_.technologies;
    p.machine_functions = cc2_.machine_functions;
    safe_z_ = stock.max[2] + o_.clearance;
    security_z_ = std::max(cc2_.setup.its_secplane.position.location.z, stock.max[2] + std::max(10.0, o_.clearance));
    for (const auto* ws : steps) {
      security_z_ = std::max(security_z_, ws->its_secplane.position.location.z);
    }
    for (const auto* ws : steps) workingstep(*ws);
    if (at_) add_rapid({*at_, {at_->x, at_->y, security_z_}});
    p.setup.its_secplane.position.location.z = security_z_;
    for (auto& e : p.main_workplan.its_elements) {
      std::visit([&](auto& x) { x.its_secplane = p.setup.its_secplane; }, e);
    }
    return std::move(out_);
  }

 private:
  void check_refs(const sn::MachiningWorkingstep& ws) const {
    auto bad = [&](const std::string& what) { throw InputError({o_.source_name, 0, 0}, "workingstep '" + ws.its_id + "': " + what); };
    if (ws.its_feature.index >= cc2_.features.size()) bad("its feature is missing");
    if (ws.its_operation.index >= cc2_.operations.size()) bad("its operation is missing");
    const auto& mop = sn::machining_operation(cc2_.operation(ws.its_operation));
    if (mop.its_tool.index >= cc2_.tools.size()) bad("its operation's tool is missing");
    if (mop.its_technology.index >= cc2_.technologies.size()) bad("its operation's technology is missing");
    if (mop.its_machine_functions.index >= cc2_.machine_functions.size()) bad("its operation's machine functions are missing");
    if (!(cc2_.tool(mop.its_tool).dimension.diameter > 0)) bad("its tool '" + cc2_.tool(mop.its_tool).its_id + "' has no diameter");
  }

  std::string first_step_of(std::size_t feature) const {
    for (const auto& e : cc2_.main_workplan.its_elements) {
      if (const auto* ws = std::get_if<sn::MachiningWorkingstep>(&e)) {
        if (ws->its_feature.index == feature) return ws->its_id;
      }
    }
    return "";
  }

  void add_rapid(std::vector<mc::Point3> points) {
    auto list = rapid_list(points);
    if (list.its_list.empty()) return;
    sn::RapidMovement r;
    r.its_id = "RAPID" + std::to_string(++rapids_);
    r.its_toolpath = std::move(list);
    out_.cc1.main_workplan.its_elements.push_back(std::move(r));
  }

  // Through the security plane from where the tool is to `start`. When the next workingstep
  // changes the tool, the retract is a rapid movement of its own, so that the tool change
  // (which a program makes between two rapid movements, docs/gcode.md) comes at the security
  // plane; with the same tool it is one rapid movement (two would read as a tool change).
  void move_to(const mc::Point3& start) {
    const bool tool_changes = !tool_ || *tool_ != next_tool_;
    tool_ = next_tool_;
    if (at_ && tool_changes) {
      add_rapid({*at_, {at_->x, at_->y, security_z_}});
      add_rapid({{at_->x, at_->y, security_z_}, {start.x, start.y, security_z_}, start});
    } else if (at_) {
      add_rapid({*at_, {at_->x, at_->y, security_z_}, {start.x, start.y, security_z_}, start});
    } else {
      add_rapid({{start.x, start.y, security_z_}, start});
    }
  }

  sn::TechnologyRef entry_technology(sn::TechnologyRef t) {
    auto it = entry_tech_.find(t.index);
    if (it != entry_tech_.end()) return it->second;
    sn::MillingTechnology e = cc2_.technology(t);
    if (!e.feedrate) return entry_tech_[t.index] = t;
    *e.feedrate *= o_.entry_feed_ratio;
    auto& techs = out_.cc1.technologies;
    auto found = std::find(techs.begin(), techs.end(), e);
    sn::TechnologyRef ref{static_cast<std::uint32_t>(found - techs.begin())};
    if (found == techs.end()) techs.push_back(e);
    return entry_tech_[t.index] = ref;
  }

  void push(sn::Feature feature, sn::Operation op, const sn::MachiningWorkingstep& ws) {
    auto& p = out_.cc1;
    p.features.push_back(std::move(feature));
    p.operations.push_back(std::move(op));
    sn::MachiningWorkingstep out;
    out.its_id = ws.its_id;
    out.its_feature = {static_cast<std::uint32_t>(p.features.size() - 1)};
    out.its_operation = {static_cast<std::uint32_t>(p.operations.size() - 1)};
    out.source = ws.source;
    p.main_workplan.its_elements.push_back(std::move(out));
  }

  void workingstep(const sn::MachiningWorkingstep& ws) {
    const auto& feature = cc2_.feature(ws.its_feature);
    const auto& op = cc2_.operation(ws.its_operation);
    const auto& mop = sn::machining_operation(op);
    next_tool_ = mop.its_tool.index;
    auto fail = [&](const std::string& what) { throw InputError({o_.source_name, 0, 0}, "workingstep '" + ws.its_id + "': " + what); };
    if (std::holds_alternative<sn::ToolpathFeature>(feature) || std::holds_alternative<sn::FreeformOperation>(op)) {
      // Already CC1: its toolpath is what it is.
      if (!mop.its_toolpath || mop.its_toolpath->its_list.empty()) {
        fail(std::string(sn::entity_name(op)) + " on " + std::string(sn::entity_name(feature)) + " without a toolpath: nothing to generate it from");
      }
      const auto first = first_point(*mop.its_toolpath), last = last_point(*mop.its_toolpath);
      if (first) move_to(*first);
      push(feature, op, ws);
      if (last) at_ = *last;
      return;
    }
    if (const auto* drilling = as_drilling(op)) {
      drill(ws, feature, op, *drilling);
      return;
    }
    if (!is_milling(op)) fail(std::string(sn::entity_name(op)) + " is not supported");
    const ShapedFeature* shaped = part_->feature(ws.its_feature.index);
    MillingInput in;
    in.feature = shaped;
    in.cc2_feature = &feature;
    in.operation = &op;
    in.tool = &cc2_.tool(mop.its_tool);
    in.technology = &cc2_.technology(mop.its_technology);
    in.workingstep = ws.its_id;
    in.safe_z = safe_z_;
    MillingOutput made = mill(*part_, in, o_, out_.warnings);
    if (made.motion.empty()) return;
    sn::FreeformOperation freeform;
    freeform.its_id = mop.its_id;
    freeform.retract_plane = safe_z_;
    freeform.its_tool = mop.its_tool;
    freeform.its_technology = mop.its_technology;
    freeform.its_machine_functions = mop.its_machine_functions;
    freeform.its_toolpath = toolpath_list(made.motion, entry_technology(mop.its_technology));
    sn::ToolpathFeature tf;
    tf.its_id = sn::feature_id(feature);
    double lowest = made.motion.start.z;
    for (const auto& m : made.motion.moves) lowest = std::min(lowest, m.end.z);
    tf.depth.position.location.z = lowest;
    move_to(made.motion.start);
    push(std::move(tf), std::move(freeform), ws);
    at_ = made.motion.end();
  }

  void drill(const sn::MachiningWorkingstep& ws, const sn::Feature& feature, const sn::Operation& op,
             const sn::DrillingTypeOperation& d) {
    auto fail = [&](const std::string& what) { throw InputError({o_.source_name, 0, 0}, "workingstep '" + ws.its_id + "': " + what); };
    const auto* hole = std::get_if<sn::RoundHole>(&feature);
    if (!hole) fail(std::string(sn::entity_name(op)) + " needs a ROUND_HOLE, not a " + std::string(sn::entity_name(feature)));
    const ShapedFeature* shaped = part_->feature(ws.its_feature.index);
    const auto& region = shaped->region;
    const auto& tool = cc2_.tool(d.its_tool);
    const mc::CutterShape cutter = mc::cutter_of(tool);
    const double hole_d = 2 * *region.hole_radius, tool_d = tool.dimension.diameter;
    const bool sizes_hole = tool.body == sn::ToolBody::TwistDrill || tool.body == sn::ToolBody::Reamer ||
                            tool.body == sn::ToolBody::BoringTool || tool.body == sn::ToolBody::Endmill;
    if (sizes_hole && tool_d > hole_d + hole->diameter.upper_limit + 1e-6) {
      fail("tool '" + tool.its_id + "' (diameter " + std::to_string(tool_d) + " mm) is larger than hole '" + region.id + "'");
    }
    sn::Operation out = op;
    auto* o = as_drilling(out);
    o->its_toolpath.reset();
    const double point = cutter.kind == mc::CutterShape::Kind::Cone ? cutter.height_at(cutter.radius) : 0;
    double depth = region.depth;
    if (d.cutting_depth) {
      if (!(*d.cutting_depth > 0)) fail("cutting_depth must be positive");
      depth = *d.cutting_depth;
    }
    // A through hole's sizing tools (drill, reamer, boring bar) go through with their full
    // diameter; a centre or spot drill only marks the hole's start.
    if (region.through && sizes_hole && !std::holds_alternative<sn::CenterDrilling>(op)) {
      const double through = region.depth + point + o_.breakthrough;
      if (depth < through - 1e-9) {
        if (d.cutting_depth) out_.warnings.push_back(ws.its_id + ": cutting depth " + std::to_string(depth) + " mm does not break through with the full diameter: " + std::to_string(through) + " mm");
        depth = through;
      }
    }
    o->cutting_depth = depth;
    const double retract = d.retract_plane.value_or(o_.clearance);
    if (!(retract > 0)) fail("the retract plane must be above the hole");
    o->retract_plane = retract;
    if (auto* m = std::get_if<sn::MultistepDrilling>(&out)) {
      if (m->depth_of_step <= 0) m->depth_of_step = tool_d;
      if (m->first_depth <= 0) m->first_depth = m->depth_of_step;
      if (m->retract_distance < 0) fail("a negative retract distance makes no sense");
    }
    const mc::Point3 above{region.frame.origin.x, region.frame.origin.y, region.top_z + retract};
    move_to(above);
    // The CC1 hole is where the tool goes (as the cc1_builder writes a cycle's hole): its depth
    // plane at the cutting depth.
    sn::RoundHole drilled = *hole;
    drilled.depth.position.location.z = -depth;
    push(drilled, std::move(out), ws);
    at_ = above;
    const PolygonSet disk = PolygonSet::from_curves({mc::circle(region.frame.origin, cutter.radius)}, kArcTolerance);
    part_->record_cut(disk, region.top_z - depth + point);
  }

  static std::optional<mc::Point3> first_point(const sn::ToolpathList& list) {
    for (const auto& t : list.its_list) {
      for (const auto& s : t.basiccurve.segments) {
        if (const auto* l = std::get_if<sn::Polyline>(&s)) {
          if (!l->points.empty()) return mc::Point3{l->points.front().x, l->points.front().y, l->points.front().z};
        } else {
          const auto& a = std::get<sn::TrimmedCircle>(s);
          return mc::Point3{a.trim_1_point.x, a.trim_1_point.y, a.trim_1_point.z};
        }
      }
    }
    return std::nullopt;
  }

  static std::optional<mc::Point3> last_point(const sn::ToolpathList& list) {
    for (auto t = list.its_list.rbegin(); t != list.its_list.rend(); ++t) {
      for (auto s = t->basiccurve.segments.rbegin(); s != t->basiccurve.segments.rend(); ++s) {
        if (const auto* l = std::get_if<sn::Polyline>(&*s)) {
          if (!l->points.empty()) return mc::Point3{l->points.back().x, l->points.back().y, l->points.back().z};
        } else {
          const auto& a = std::get<sn::TrimmedCircle>(*s);
          return mc::Point3{a.trim_2_point.x, a.trim_2_point.y, a.trim_2_point.z};
        }
      }
    }
    return std::nullopt;
  }

  const sn::Project& cc2_;
  const Options& o_;
  GeneratedToolpaths out_;
  PartModel* part_ = nullptr;
  double safe_z_ = 0, security_z_ = 0;
  std::optional<mc::Point3> at_;
  std::optional<std::uint32_t> tool_;  // the tool of the last workingstep moved to
  std::uint32_t next_tool_ = 0;        // the tool of the workingstep being generated
  int rapids_ = 0;
  std::map<std::uint32_t, sn::TechnologyRef> entry_tech_;
};

}  // namespace

GeneratedToolpaths generate_toolpaths(const stepnc::Project& cc2, const Options& options) {
  return Generator(cc2, options).run();
}

}  // namespace ncbridge::toolpath_generator
