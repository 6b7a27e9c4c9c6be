// Features read but not planned for milling: turning features (outer_round, revolved_profile,
// thread, chamfer, their tapers) and kinds this reader does not map, with every parameter the
// file gives them and their components.
#include <cstdio>

#include "ap224_features.hpp"
#include "ncbridge/part_reader/setup_frame.hpp"

namespace ncbridge::part_reader::ap224 {

namespace {

std::string point_text(const stepnc::CartesianPoint& p) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "(%.6g, %.6g, %.6g) mm", p.x, p.y, p.z);
  return buf;
}

void add_parameters(const Parameters& p, const std::string& prefix, std::vector<Parameter>& out) {
  for (const auto& [name, placement] : p.placements) {
    out.push_back({prefix + (name.empty() ? "placement" : name), point_text(placement.location) + " axis " + direction_text(placement.axis)});
  }
  for (const auto& [name, value] : p.listing) out.push_back({prefix + name, value});
  for (const auto& [name, d] : p.directions) out.push_back({prefix + (name.empty() ? "direction" : name), direction_text(d)});
}

}  // namespace

ListedFeature list_feature(const Graph& g, InstanceId id, const std::string& entity, const std::string& reason) {
  ListedFeature l;
  l.entity = entity;
  l.source = where(id);
  l.name = g.description_of(g.at(id));
  l.reason = reason;
  add_parameters(g.parameters(id), "", l.parameters);
  for (const auto& c : g.components(id)) {
    const auto& ci = g.at(c.id);
    std::string kind = ci.records.front().entity;
    if (ci.complex) {  // name the component by its most specific record
      for (const auto& r : ci.records) {
        if (r.entity != "SHAPE_ASPECT" && r.entity != "CHARACTERIZED_OBJECT" && r.entity != "FEATURE_DEFINITION") kind = r.entity;
      }
    }
    std::string label = kind;
    if (const auto t = g.aspect_text(ci); t && !t->second.empty()) label += " '" + t->second + "'";
    if (!c.relation_name.empty()) label += " (" + c.relation_name + ")";
    const Parameters p = g.parameters(c.id);
    if (p.listing.empty() && p.placements.empty() && p.directions.empty()) continue;  // a relation to another feature
    add_parameters(p, label + ": ", l.parameters);
  }
  return l;
}

std::optional<PartStock> read_stock(const Graph& g, std::vector<Warning>& warnings) {
  std::optional<PartStock> stock;
  for (const auto& instance : g.graph().instances()) {
    const bool block = Graph::is(instance, "BLOCK_SHAPE_REPRESENTATION");
    const bool cylinder = Graph::is(instance, "CYLINDRICAL_SHAPE_REPRESENTATION");
    if (!block && !cylinder) continue;
    if (stock) {
      warnings.push_back({where(instance.id), "a second stock shape: the first (" + stock->source + ") is used"});
      continue;
    }
    const Parameters p = g.representation(instance.id);
    PartStock s;
    s.source = where(instance.id);
    s.placement = orientation(p).value_or(stepnc::Axis2Placement3d{});
    auto length = [&](const char* name) {
      auto it = p.lengths.find(name);
      if (it == p.lengths.end() || !(it->second > 0)) g.fail(instance.id, std::string("the stock needs a positive '") + name + "'");
      return it->second;
    };
    if (block) {
      s.shape = StockShape::Block;
      s.length = length("length");
      s.width = length("width");
      s.height = length("height");
    } else {
      s.shape = StockShape::Cylinder;
      s.length = length("length");
      s.diameter = length("diameter");
    }
    stock = s;
  }
  return stock;
}

}  // namespace ncbridge::part_reader::ap224
