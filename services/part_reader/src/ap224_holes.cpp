// ROUND_HOLE (diameter from its circular_closed_profile, depth and direction from its linear
// path_feature_component, the hole_bottom) and COMPOSITE_HOLE (counterbore, countersunk).
#include <algorithm>
#include <cmath>

#include "ap224_features.hpp"

namespace ncbridge::part_reader::ap224 {

ReadFeature read_round_hole(const Graph& g, InstanceId id) {
  ReadFeature out;
  const Parameters own = g.parameters(id);
  const auto placement = orientation(own);
  if (!placement) g.fail(id, "the hole has no placement ('orientation')");
  const auto components = g.components(id);

  const Component* profile = find_component(g, components, {"CIRCULAR_CLOSED_PROFILE"}, "diameter occurrence");
  if (!profile) g.fail(id, "the hole has no circular_closed_profile (its diameter)");
  const Parameters profile_parameters = g.parameters(profile->id);
  const double diameter = required_length(g, id, profile->id, profile_parameters, "diameter");
  if (!(diameter > 0)) g.fail(id, "the hole's diameter must be positive");

  const Component* path = find_component(g, components, {"PATH_FEATURE_COMPONENT"}, "hole depth occurrence");
  if (!path) g.fail(id, "the hole has no path_feature_component (its depth)");
  const Parameters path_parameters = g.parameters(path->id);
  const double depth = required_length(g, id, path->id, path_parameters, "distance");
  if (!(depth > 0)) g.fail(id, "the hole's depth must be positive");
  // The path runs from the placement into the material.
  const stepnc::Direction into = any_direction(path_parameters).value_or(placement->axis);

  Feature f;
  f.kind = FeatureKind::RoundHole;
  f.source = where(id);
  f.name = g.description_of(g.at(id));
  f.placement.location = placement->location;
  f.placement.axis = negate(into);
  f.placement.ref_direction = normal_part(placement->ref_direction, f.placement.axis);
  f.depth = depth;
  f.diameter = diameter;
  f.outline = Outline::Circle;
  if (auto t = profile_parameters.tolerances.find("diameter"); t != profile_parameters.tolerances.end()) f.diameter_tolerance = t->second;

  if (const Component* bottom = find_component(g, components, {"HOLE_BOTTOM"}, "bottom condition occurrence")) {
    const auto text = g.aspect_text(g.at(bottom->id));
    const std::string condition = text ? text->second : "";
    const Parameters b = g.parameters(bottom->id);
    if (condition == "through") {
      f.bottom = HoleBottom::Through;
    } else if (condition == "flat") {
      f.bottom = HoleBottom::Flat;
    } else if (condition == "flat with radius") {
      f.bottom = HoleBottom::FlatWithRadius;
      f.bottom_radius = required_length(g, id, bottom->id, b, "corner radius");
    } else if (condition == "spherical") {
      f.bottom = HoleBottom::Spherical;
      f.bottom_radius = required_length(g, id, bottom->id, b, "radius");
    } else if (condition == "conical") {
      f.bottom = HoleBottom::Conical;
      auto angle = b.angles.find("tip angle");
      if (angle == b.angles.end()) {
        f.tip_angle = 118;
        out.warnings.push_back({where(id), "conical hole bottom without a 'tip angle': 118 degrees assumed"});
      } else {
        f.tip_angle = angle->second;
      }
    } else if (condition == "flat with taper") {
      f.bottom = HoleBottom::Flat;
      out.warnings.push_back({where(id), "hole bottom 'flat with taper' read as flat (the taper is not planned)"});
    } else {
      g.fail(bottom->id, "unknown hole bottom condition '" + condition + "'");
    }
  } else {
    out.warnings.push_back({where(id), "the hole has no hole_bottom: read as flat"});
  }
  if (find_component(g, components, {"TAPER"}, "change in diameter occurrence")) {
    out.warnings.push_back({where(id), "the hole's change in diameter (taper) is not planned: drilled straight"});
  }
  out.feature = std::move(f);
  return out;
}

std::optional<Compound> read_composite_hole(const Graph& g, InstanceId id, const std::vector<std::pair<InstanceId, std::size_t>>& holes,
                                            const std::vector<Feature>& features, std::vector<Warning>& warnings) {
  const std::string description = g.description_of(g.at(id));
  Compound c;
  c.source = where(id);
  if (description == "counterbore") {
    c.kind = CompoundKind::Counterbore;
  } else if (description == "countersunk") {
    c.kind = CompoundKind::Countersink;
  } else {
    warnings.push_back({where(id), "composite hole '" + description + "' is neither a counterbore nor countersunk: its holes are planned one by one"});
    return std::nullopt;
  }
  for (const auto& component : g.components(id)) {
    for (const auto& [hole, index] : holes) {
      if (component.id == hole && std::find(c.elements.begin(), c.elements.end(), index) == c.elements.end()) c.elements.push_back(index);
    }
  }
  if (c.elements.size() < 2) {
    warnings.push_back({where(id), "composite hole with fewer than two round holes: ignored"});
    return std::nullopt;
  }
  std::sort(c.elements.begin(), c.elements.end(),
            [&](std::size_t a, std::size_t b) { return features[a].diameter > features[b].diameter; });
  const auto& first = features[c.elements.front()].placement;
  for (std::size_t e : c.elements) {
    const auto& p = features[e].placement;
    const double dx = p.location.x - first.location.x, dy = p.location.y - first.location.y, dz = p.location.z - first.location.z;
    const auto& a = first.axis;
    const double along = dx * a.x + dy * a.y + dz * a.z;
    const double off = std::sqrt(std::max(0.0, dx * dx + dy * dy + dz * dz - along * along));
    if (dot(p.axis, a) < 1 - 1e-6 || off > 1e-3) {
      warnings.push_back({where(id), "the holes of the " + description + " do not share one axis: planned one by one"});
      return std::nullopt;
    }
  }
  return c;
}

}  // namespace ncbridge::part_reader::ap224
