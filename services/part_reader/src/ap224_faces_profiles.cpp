// FLAT_FACE (the planar face: a linear course of travel, a linear_profile removal boundary and a
// removal depth) and OUTSIDE_PROFILE (a closed boundary profile swept along a linear path).
#include <cmath>
#include <numbers>

#include "ap224_features.hpp"

namespace ncbridge::part_reader::ap224 {

namespace {

std::optional<stepnc::Direction> named_direction(const Parameters& p, const char* name) {
  if (auto it = p.directions.find(name); it != p.directions.end()) return it->second;
  return std::nullopt;
}

// The top of a block stock along `up` seen from `from`.
std::optional<double> stock_above(const PartStock& stock, const stepnc::CartesianPoint& from, const stepnc::Direction& up) {
  if (stock.shape != StockShape::Block) return std::nullopt;
  const auto& p = stock.placement;
  const stepnc::Direction x = p.ref_direction, z = p.axis, y = cross(z, x);
  double top = -1e300;
  for (int i = 0; i < 8; ++i) {
    stepnc::CartesianPoint c = p.location;
    c = moved(c, x, (i & 1) ? stock.length : 0);
    c = moved(c, y, (i & 2) ? stock.width : 0);
    c = moved(c, z, (i & 4) ? stock.height : 0);
    top = std::max(top, dot({c.x - from.x, c.y - from.y, c.z - from.z}, up));
  }
  return top;
}

}  // namespace

ReadFeature read_flat_face(const Graph& g, InstanceId id, const std::optional<PartStock>& stock) {
  ReadFeature out;
  const Parameters own = g.parameters(id);
  const auto placement = orientation(own);
  if (!placement) g.fail(id, "the face has no placement ('orientation')");
  const auto components = g.components(id);
  const Component* course = find_component(g, components, {"PATH_FEATURE_COMPONENT"}, "course of travel occurrence");
  const Component* boundary = find_component(g, components, {"LINEAR_PROFILE"}, "removal boundary occurrence");
  if (!course || !boundary) g.fail(id, "the face needs a course of travel and a linear profile removal boundary");
  const Parameters cp = g.parameters(course->id);
  const Parameters bp = g.parameters(boundary->id);
  const double length = required_length(g, id, course->id, cp, "distance");
  const double width = required_length(g, id, boundary->id, bp, "profile length");
  const stepnc::Direction up = named_direction(own, "removal direction").value_or(placement->axis);
  const stepnc::Direction along = normal_part(any_direction(cp).value_or(placement->ref_direction), up);
  stepnc::Direction across = cross(up, along);
  if (auto q = orientation(bp); q && dot(q->ref_direction, across) < 0) across = negate(across);
  double depth = 0;
  if (auto d = own.lengths.find("removal depth"); d != own.lengths.end()) {
    depth = d->second;
  } else if (stock) {
    depth = stock_above(*stock, placement->location, up).value_or(0);
  }
  if (!(depth > 0)) {
    out.listed = list_feature(g, id, "FLAT_FACE", "no material to remove: the face gives no removal depth and lies at the stock's top");
    return out;
  }
  Feature f;
  f.kind = FeatureKind::PlanarFace;
  f.source = where(id);
  f.name = g.description_of(g.at(id));
  f.outline = Outline::Rectangle;
  f.length = length;
  f.width = width;
  f.depth = depth;
  f.placement.axis = up;
  f.placement.ref_direction = along;
  f.placement.location = moved(moved(moved(placement->location, along, length / 2), across, width / 2), up, depth);
  out.feature = std::move(f);
  return out;
}

ReadFeature read_outside_profile(const Graph& g, InstanceId id) {
  ReadFeature out;
  const Parameters own = g.parameters(id);
  const auto placement = orientation(own);
  const auto components = g.components(id);
  const Component* profile = find_component(g, components, {"RECTANGULAR_CLOSED_PROFILE", "CIRCULAR_CLOSED_PROFILE", "NGON_CLOSED_PROFILE"});
  const Component* path = find_component(g, components, {"PATH_FEATURE_COMPONENT"});
  if (!profile) {
    out.listed = list_feature(g, id, "OUTSIDE_PROFILE", "its boundary is not a rectangular, circular or ngon profile");
    return out;
  }
  if (!path) {
    out.listed = list_feature(g, id, "OUTSIDE_PROFILE", "the file gives no depth (no 'profile swept shape' path): not planned");
    return out;
  }
  const Parameters pp = g.parameters(profile->id);
  const Parameters wp = g.parameters(path->id);
  const double depth = required_length(g, id, path->id, wp, "distance");
  const auto q = orientation(pp) ? orientation(pp) : placement;
  if (!q) g.fail(id, "the profile has no placement");
  const stepnc::Direction up = named_direction(own, "removal direction").value_or(any_direction(wp) ? negate(*any_direction(wp)) : q->axis);
  Feature f;
  f.kind = FeatureKind::GeneralOutsideProfile;
  f.source = where(id);
  f.name = g.description_of(g.at(id));
  f.depth = depth;
  f.placement.location = q->location;
  f.placement.axis = up;
  f.placement.ref_direction = normal_part(q->ref_direction, up);
  const auto& pi = g.at(profile->id);
  if (Graph::is(pi, "RECTANGULAR_CLOSED_PROFILE")) {
    f.outline = Outline::Rectangle;
    f.length = required_length(g, id, profile->id, pp, "length");
    f.width = required_length(g, id, profile->id, pp, "width");
    if (auto r = pp.lengths.find("corner radius"); r != pp.lengths.end()) f.corner_radius = r->second;
  } else if (Graph::is(pi, "CIRCULAR_CLOSED_PROFILE")) {
    f.outline = Outline::Circle;
    f.diameter = required_length(g, id, profile->id, pp, "diameter");
  } else {
    const auto sides = pp.counts.find("number of sides");
    if (sides == pp.counts.end() || sides->second < 3 || sides->second > 1000) g.fail(profile->id, "an ngon needs 3 or more 'number of sides'");
    const int n = static_cast<int>(std::lround(sides->second));
    double radius = 0;
    if (auto c = pp.lengths.find("circumscribed diameter"); c != pp.lengths.end()) radius = c->second / 2;
    else radius = required_length(g, id, profile->id, pp, "diameter across flats") / 2 / std::cos(std::numbers::pi / n);
    f.outline = Outline::General;
    for (int k = 0; k < n; ++k) {
      const double a = 2 * std::numbers::pi * k / n;
      f.boundary.push_back({radius * std::cos(a), radius * std::sin(a)});
    }
  }
  out.feature = std::move(f);
  return out;
}

}  // namespace ncbridge::part_reader::ap224
