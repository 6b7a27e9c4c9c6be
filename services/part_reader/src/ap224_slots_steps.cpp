// SLOT (a square_u_profile swept along a linear course of travel, with its two slot ends) and
// STEP (a vee_profile removal boundary swept along a linear course of travel).
//
// Profile placements follow the file's own profiles: a U profile lies in its placement's xy
// plane with the origin at the middle of the U's floor, x across the U, y towards its opening
// (out of the material), z along the sweep. A step's vee profile has its origin at the corner
// of wall and floor, x along the floor towards the open side, y up the wall, z along the course.
#include <algorithm>
#include <cmath>

#include "ap224_features.hpp"

namespace ncbridge::part_reader::ap224 {

namespace {

// How far from `from` along `direction` the stock's boundary lies (for steps that leave their
// width and height to the stock).
std::optional<double> to_stock_boundary(const PartStock& stock, const stepnc::CartesianPoint& from, const stepnc::Direction& direction) {
  if (stock.shape != StockShape::Block) return std::nullopt;
  const auto& p = stock.placement;
  const stepnc::Direction x = p.ref_direction, z = p.axis, y = cross(z, x);
  const stepnc::Direction rel{from.x - p.location.x, from.y - p.location.y, from.z - p.location.z};
  const double local[3] = {dot(rel, x), dot(rel, y), dot(rel, z)};
  const double dir[3] = {dot(direction, x), dot(direction, y), dot(direction, z)};
  const double size[3] = {stock.length, stock.width, stock.height};
  double best = 1e300;
  for (int i = 0; i < 3; ++i) {
    if (std::abs(dir[i]) < 1e-9) continue;
    const double t = dir[i] > 0 ? (size[i] - local[i]) / dir[i] : -local[i] / dir[i];
    if (t >= -1e-9) best = std::min(best, t);
  }
  if (best == 1e300) return std::nullopt;
  return std::max(best, 0.0);
}

}  // namespace

ReadFeature read_slot(const Graph& g, InstanceId id) {
  ReadFeature out;
  const Parameters own = g.parameters(id);
  const auto placement = orientation(own);
  const auto components = g.components(id);

  const Component* swept = find_component(g, components, {"SQUARE_U_PROFILE", "ROUNDED_U_PROFILE"}, "swept shape occurrence");
  if (!swept) {
    out.listed = list_feature(g, id, "SLOT", "its swept shape is not a square or rounded U profile");
    return out;
  }
  const Component* course = find_component(g, components, {"PATH_FEATURE_COMPONENT"}, "course of travel occurrence");
  if (!course) g.fail(id, "the slot has no course of travel (path_feature_component)");
  const auto course_text = g.aspect_text(g.at(course->id));
  if (course_text && course_text->second != "linear") {
    out.listed = list_feature(g, id, "SLOT", "course of travel '" + course_text->second + "': only linear slots are planned");
    return out;
  }
  const Parameters sp = g.parameters(swept->id);
  const Parameters cp = g.parameters(course->id);
  const double width = required_length(g, id, swept->id, sp, "width");
  const double length = required_length(g, id, course->id, cp, "distance");
  if (!(width > 0) || !(length >= 0)) g.fail(id, "the slot's width must be positive and its length not negative");
  const auto depth_it = sp.lengths.find("depth");
  if (depth_it == sp.lengths.end()) g.fail(id, "the slot's U profile " + where(swept->id) + " gives no 'depth'");
  const double depth = depth_it->second;
  if (!(depth > 0)) g.fail(id, "the slot's depth must be positive");

  const auto profile_placement = orientation(sp);
  if (!profile_placement && !placement) g.fail(id, "the slot has no placement");
  stepnc::Direction up, along;
  stepnc::CartesianPoint floor_start;
  if (profile_placement) {
    up = cross(profile_placement->axis, profile_placement->ref_direction);
    along = any_direction(cp).value_or(profile_placement->axis);
    floor_start = profile_placement->location;
  } else {  // the feature's placement: z into the material (as a hole's), x along the course
    up = negate(placement->axis);
    along = any_direction(cp).value_or(placement->ref_direction);
    floor_start = moved(placement->location, up, -depth);
  }
  along = normal_part(along, up);

  Feature f;
  f.kind = FeatureKind::Slot;
  f.source = where(id);
  f.name = g.description_of(g.at(id));
  f.placement.location = moved(floor_start, up, depth);
  f.placement.axis = up;
  f.placement.ref_direction = along;
  f.depth = depth;
  f.length = length;
  f.width = width;
  f.floor_radius = std::max(optional_length(sp, "first radius"), optional_length(sp, "second radius"));
  f.outline = Outline::Rectangle;
  if (Graph::is(g.at(swept->id), "ROUNDED_U_PROFILE")) {
    f.floor_radius = width / 2;
    out.warnings.push_back({where(id), "rounded U slot: its round floor needs a ball end mill of the slot's width"});
  }
  for (const char* angle : {"first angle", "second angle"}) {
    if (auto a = sp.angles.find(angle); a != sp.angles.end() && std::abs(a->second - 90) > 1e-6) {
      out.warnings.push_back({where(id), std::string("slot wall ") + angle + " " + std::to_string(a->second) + " deg: milled as a square slot"});
    }
  }
  int ends_seen = 0;
  for (const auto& c : components) {
    if (!Graph::is(g.at(c.id), "SLOT_END")) continue;
    const auto t = g.aspect_text(g.at(c.id));
    const std::string kind = t ? t->second : "";
    SlotEnd end = SlotEnd::Open;
    if (kind == "radiused" || kind == "loop") end = SlotEnd::Radiused;
    else if (kind == "flat" || kind == "woodruff") end = SlotEnd::Flat;
    else if (kind != "open") g.fail(c.id, "unknown slot end '" + kind + "'");
    const std::size_t which = c.relation_name == "course of travel end" ? 1 : c.relation_name == "course of travel start" ? 0 : static_cast<std::size_t>(std::min(ends_seen, 1));
    f.slot_ends[which] = end;
    ++ends_seen;
  }
  // The placement at the middle of the course, as for the other outlined features.
  f.placement.location = moved(f.placement.location, along, length / 2);
  out.feature = std::move(f);
  return out;
}

ReadFeature read_step(const Graph& g, InstanceId id, const std::optional<PartStock>& stock) {
  ReadFeature out;
  const auto components = g.components(id);
  const Component* course = find_component(g, components, {"PATH_FEATURE_COMPONENT"}, "course of travel occurrence");
  const Component* boundary = find_component(g, components, {"VEE_PROFILE"}, "removal boundary occurrence");
  if (!course || !boundary) g.fail(id, "the step needs a course of travel and a vee profile removal boundary");
  const Parameters cp = g.parameters(course->id);
  const Parameters vp = g.parameters(boundary->id);
  const double length = required_length(g, id, course->id, cp, "distance");
  const auto q = orientation(vp);
  if (!q) g.fail(boundary->id, "the step's vee profile has no placement");
  if (auto a = vp.angles.find("profile angle"); a != vp.angles.end() && std::abs(a->second - 90) > 1e-6) {
    out.listed = list_feature(g, id, "STEP", "vee profile angle " + std::to_string(a->second) + " deg: only square steps are planned");
    return out;
  }
  const stepnc::Direction up = cross(q->axis, q->ref_direction);
  const stepnc::Direction outward = q->ref_direction;
  const stepnc::Direction along = normal_part(any_direction(cp).value_or(q->axis), up);
  double width = optional_length(vp, "first length");
  double height = optional_length(vp, "second length");
  if (width <= 0 || height <= 0) {
    if (!stock) g.fail(id, "the step gives no lengths and the file no stock to take them from");
    if (width <= 0) width = to_stock_boundary(*stock, q->location, outward).value_or(0);
    if (height <= 0) height = to_stock_boundary(*stock, q->location, up).value_or(0);
    if (width <= 0 || height <= 0) g.fail(id, "the step's width or height does not reach the stock's boundary");
  }
  Feature f;
  f.kind = FeatureKind::Step;
  f.source = where(id);
  f.name = g.description_of(g.at(id));
  f.outline = Outline::Rectangle;
  f.length = length;
  f.width = width;
  f.depth = height;
  f.floor_radius = optional_length(vp, "profile radius");
  f.placement.axis = up;
  f.placement.ref_direction = along;
  f.placement.location = moved(moved(moved(q->location, along, length / 2), outward, width / 2), up, height);
  out.feature = std::move(f);
  return out;
}

}  // namespace ncbridge::part_reader::ap224
