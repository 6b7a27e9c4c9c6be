#include <cmath>

#include "ap224_features.hpp"

namespace ncbridge::part_reader::ap224 {

double required_length(const Graph& g, InstanceId feature, InstanceId component, const Parameters& p, const char* name) {
  auto it = p.lengths.find(name);
  if (it == p.lengths.end()) {
    g.fail(feature, std::string("its ") + g.at(component).records.front().entity + " " + where(component) + " gives no '" + name + "'");
  }
  return it->second;
}

double optional_length(const Parameters& p, const char* name) {
  auto it = p.lengths.find(name);
  return it == p.lengths.end() ? 0.0 : it->second;
}

std::string where(InstanceId id) {
  std::string text = "#";
  text += std::to_string(id);
  return text;
}

const Component* find_component(const Graph& g, const std::vector<Component>& components,
                                std::initializer_list<const char*> entities, const char* aspect) {
  const Component* any = nullptr;
  for (const auto& c : components) {
    const auto& instance = g.at(c.id);
    bool kind = false;
    for (const char* e : entities) kind = kind || Graph::is(instance, e);
    if (!kind) continue;
    if (!aspect || c.aspect == aspect) return &c;
    if (!any) any = &c;
  }
  return any;
}

stepnc::Direction negate(const stepnc::Direction& d) { return {-d.x, -d.y, -d.z}; }

stepnc::Direction cross(const stepnc::Direction& a, const stepnc::Direction& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

double dot(const stepnc::Direction& a, const stepnc::Direction& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

stepnc::Direction normal_part(const stepnc::Direction& ref, const stepnc::Direction& axis) {
  auto project = [&](const stepnc::Direction& r) {
    const double d = dot(r, axis);
    stepnc::Direction n{r.x - d * axis.x, r.y - d * axis.y, r.z - d * axis.z};
    const double len = std::sqrt(dot(n, n));
    return len > 1e-9 ? std::optional<stepnc::Direction>(stepnc::Direction{n.x / len, n.y / len, n.z / len}) : std::nullopt;
  };
  if (auto n = project(ref)) return *n;
  if (auto n = project({1, 0, 0})) return *n;
  return *project({0, 1, 0});
}

stepnc::CartesianPoint moved(const stepnc::CartesianPoint& p, const stepnc::Direction& d, double distance) {
  return {p.x + d.x * distance, p.y + d.y * distance, p.z + d.z * distance};
}

std::optional<stepnc::Axis2Placement3d> orientation(const Parameters& p) {
  if (auto it = p.placements.find("orientation"); it != p.placements.end()) return it->second;
  if (!p.placements.empty()) return p.placements.begin()->second;
  return std::nullopt;
}

std::optional<stepnc::Direction> any_direction(const Parameters& p) {
  if (p.directions.empty()) return std::nullopt;
  return p.directions.begin()->second;
}

std::vector<OutlineVertex> local_outline(const std::vector<std::pair<stepnc::CartesianPoint, bool>>& corners,
                                         const stepnc::Axis2Placement3d& placement) {
  const stepnc::Direction x = placement.ref_direction, y = cross(placement.axis, placement.ref_direction);
  std::vector<OutlineVertex> out;
  double area = 0;
  for (const auto& [p, open] : corners) {
    const stepnc::Direction d{p.x - placement.location.x, p.y - placement.location.y, p.z - placement.location.z};
    out.push_back({dot(d, x), dot(d, y), 0, open});
  }
  for (std::size_t i = 0; i < out.size(); ++i) {
    const auto& a = out[i];
    const auto& b = out[(i + 1) % out.size()];
    area += a.x * b.y - b.x * a.y;
  }
  if (area < 0) {  // reverse; the edge i -> i+1 becomes i+1 -> i, owned by i+1
    std::vector<OutlineVertex> reversed;
    const std::size_t n = out.size();
    for (std::size_t k = 0; k < n; ++k) {
      const std::size_t i = n - 1 - k;
      OutlineVertex v = out[i];
      v.open = out[(i + n - 1) % n].open;
      reversed.push_back(v);
    }
    out = std::move(reversed);
  }
  return out;
}

}  // namespace ncbridge::part_reader::ap224
