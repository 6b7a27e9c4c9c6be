// POCKET: 'closed rectangular' (rectangular_closed_profile), 'circular cutout' and 'complex'
// (circular, ngon or rectangular closed profile), 'open rectangular' (square_u_profile), with the
// depth from its linear path_feature_component and its pocket_bottom.
#include <cmath>
#include <numbers>

#include "ap224_features.hpp"

namespace ncbridge::part_reader::ap224 {

ReadFeature read_pocket(const Graph& g, InstanceId id) {
  ReadFeature out;
  const std::string description = g.description_of(g.at(id));
  const Parameters own = g.parameters(id);
  const auto placement = orientation(own);
  if (!placement) g.fail(id, "the pocket has no placement ('orientation')");
  const auto components = g.components(id);

  const Component* path = find_component(g, components, {"PATH_FEATURE_COMPONENT"}, "pocket depth occurrence");
  if (!path) g.fail(id, "the pocket has no path_feature_component (its depth)");
  const Parameters path_parameters = g.parameters(path->id);
  const double depth = required_length(g, id, path->id, path_parameters, "distance");
  if (!(depth > 0)) g.fail(id, "the pocket's depth must be positive");
  const stepnc::Direction into = any_direction(path_parameters).value_or(placement->axis);

  Feature f;
  f.kind = FeatureKind::ClosedPocket;
  f.source = where(id);
  f.name = description;
  f.depth = depth;
  f.floor_radius = optional_length(own, "fillet radius");
  const stepnc::Direction up = negate(into);

  if (const Component* bottom = find_component(g, components, {"POCKET_BOTTOM"}, "bottom condition occurrence")) {
    const auto text = g.aspect_text(g.at(bottom->id));
    const std::string condition = text ? text->second : "";
    if (condition == "through") f.through = true;
    else if (condition == "complex") out.warnings.push_back({where(id), "complex pocket bottom: machined flat at the pocket's depth"});
    const Parameters b = g.parameters(bottom->id);
    if (auto r = b.lengths.find("radius"); r != b.lengths.end()) f.floor_radius = r->second;
  } else if (description == "circular cutout" || description == "complex cutout") {
    f.through = true;
  }

  const Component* profile = find_component(g, components,
                                            {"RECTANGULAR_CLOSED_PROFILE", "CIRCULAR_CLOSED_PROFILE", "NGON_CLOSED_PROFILE", "SQUARE_U_PROFILE"});
  if (!profile) {
    out.listed = list_feature(g, id, "POCKET", "pocket '" + description + "': its boundary profile is not one this reader maps "
                                               "(rectangular, circular, ngon, square U)");
    return out;
  }
  const Parameters pp = g.parameters(profile->id);
  const stepnc::Axis2Placement3d q = orientation(pp).value_or(*placement);
  f.placement.location = q.location;
  f.placement.axis = up;
  f.placement.ref_direction = normal_part(q.ref_direction, up);
  const auto& pi = g.at(profile->id);
  if (Graph::is(pi, "RECTANGULAR_CLOSED_PROFILE")) {
    f.outline = Outline::Rectangle;
    f.length = required_length(g, id, profile->id, pp, "length");
    f.width = required_length(g, id, profile->id, pp, "width");
    f.corner_radius = optional_length(pp, "corner radius");
  } else if (Graph::is(pi, "CIRCULAR_CLOSED_PROFILE")) {
    f.outline = Outline::Circle;
    f.diameter = required_length(g, id, profile->id, pp, "diameter");
  } else if (Graph::is(pi, "NGON_CLOSED_PROFILE")) {
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
    f.corner_radius = optional_length(pp, "corner radius");
  } else {  // SQUARE_U_PROFILE: an open pocket, open on the U's open side
    f.kind = FeatureKind::OpenPocket;
    const double w = required_length(g, id, profile->id, pp, "width");
    const double reach = required_length(g, id, profile->id, pp, "depth");
    f.outline = Outline::General;
    // The U's placement: origin at the middle of its closed side, x across it, y towards the
    // open side; the outline is centred on the pocket's placement.
    const stepnc::Direction across = q.ref_direction;
    const stepnc::Direction open = cross(q.axis, q.ref_direction);
    f.placement.location = moved(q.location, open, reach / 2);
    const auto c0 = moved(q.location, across, -w / 2), c1 = moved(q.location, across, w / 2);
    f.boundary = local_outline({{c0, false}, {c1, false}, {moved(c1, open, reach), true}, {moved(c0, open, reach), false}}, f.placement);
    f.corner_radius = std::max(optional_length(pp, "first radius"), optional_length(pp, "second radius"));
    f.length = w;
    f.width = reach;
  }
  out.feature = std::move(f);
  return out;
}

}  // namespace ncbridge::part_reader::ap224
