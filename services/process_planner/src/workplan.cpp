#include "workplan.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>

namespace ncbridge::process_planner {

namespace sn = stepnc;

namespace {

double tidy(double v) {
  const double r = std::round(v * 1e6) / 1e6;
  return r == 0 ? 0 : r;
}

// The same tool entity the CC1 builder makes for a program's tool.
sn::ToolBody body_of(setup::ToolType type) {
  using setup::ToolType;
  switch (type) {
    case ToolType::FaceMill: return sn::ToolBody::Facemill;
    case ToolType::FlatEndMill: return sn::ToolBody::Endmill;
    case ToolType::BallEndMill: return sn::ToolBody::BallEndmill;
    case ToolType::BullNoseEndMill: return sn::ToolBody::BullnoseEndmill;
    case ToolType::Drill: return sn::ToolBody::TwistDrill;
    case ToolType::CenterDrill: case ToolType::SpotDrill: return sn::ToolBody::Centerdrill;
    case ToolType::Reamer: return sn::ToolBody::Reamer;
    case ToolType::Tap: return sn::ToolBody::Tap;
    case ToolType::BoringBar: return sn::ToolBody::BoringTool;
    case ToolType::TSlotMill: return sn::ToolBody::TSlotMill;
    case ToolType::ChamferMill: return sn::ToolBody::Countersink;
    case ToolType::Unknown: break;
  }
  return sn::ToolBody::UserDefinedTool;
}

sn::MillingCuttingTool tool_entity(const setup::Tool& tool) {
  sn::MillingCuttingTool t;
  t.number = tool.number;
  t.its_id = "T" + std::to_string(tool.number) + (tool.name.empty() ? "" : " " + tool.name);
  t.body = body_of(tool.type);
  t.dimension.diameter = tool.diameter;
  if (tool.point_angle > 0) t.dimension.tool_tip_half_angle = tool.point_angle / 2;
  if (tool.flute_length > 0) t.dimension.cutting_edge_length = tool.flute_length;
  if ((t.body == sn::ToolBody::Endmill || t.body == sn::ToolBody::Facemill || t.body == sn::ToolBody::BullnoseEndmill) &&
      tool.corner_radius > 0) {
    t.dimension.edge_radius = tool.corner_radius;
    t.dimension.edge_center_vertical = tool.corner_radius;
    t.dimension.edge_center_horizontal = tool.diameter / 2 - tool.corner_radius;
  } else if (t.body == sn::ToolBody::BallEndmill) {
    t.dimension.edge_radius = tool.diameter / 2;
    t.dimension.edge_center_vertical = tool.diameter / 2;
    t.dimension.edge_center_horizontal = 0.0;
  }
  if (tool.flutes > 0) t.number_of_teeth = tool.flutes;
  t.tool_offset_length = tool.length;
  if (tool.length > 0) t.overall_assembly_length = tool.length;
  return t;
}

}  // namespace

void build_workplan(const std::vector<FeaturePlan>& features, const setup::Stock& stock, const part_reader::Part& part,
                    const Options& options, Plan& out) {
  auto& p = out.project;
  p.its_id = !options.project_id.empty() ? options.project_id : !part.name.empty() ? part.name : "PART";
  p.workpiece.its_id = part.name.empty() ? "PART" : part.name;
  if (part.bounds) {
    sn::Block b;
    b.position.location = {tidy(part.bounds->min[0]), tidy(part.bounds->min[1]), tidy(part.bounds->min[2])};
    b.x = tidy(part.bounds->max[0] - part.bounds->min[0]);
    b.y = tidy(part.bounds->max[1] - part.bounds->min[1]);
    b.z = tidy(part.bounds->max[2] - part.bounds->min[2]);
    p.workpiece.its_bounding_geometry = b;
  }
  sn::Workpiece raw;
  raw.its_id = "RAWPIECE";
  sn::Block block;
  block.position.location = {tidy(stock.min[0]), tidy(stock.min[1]), tidy(stock.min[2])};
  block.x = tidy(stock.size(0));
  block.y = tidy(stock.size(1));
  block.z = tidy(stock.size(2));
  raw.its_bounding_geometry = block;
  p.rawpiece = raw;
  sn::Plane secplane;
  secplane.position.location.z = tidy(stock.max[2] + options.security_clearance);
  p.setup.its_secplane = secplane;
  p.machine_functions.push_back(sn::MillingMachineFunctions{true});  // flood coolant

  // Features in the part's order.
  for (const auto& f : features) {
    p.features.push_back(f.feature);
    out.features.push_back({f.part_feature, p.features.size() - 1, {}});
  }

  // Operations in workplan order.
  struct Item {
    std::size_t feature, index;
    const PlannedOperation* op;
  };
  std::vector<Item> items;
  for (std::size_t i = 0; i < features.size(); ++i) {
    for (std::size_t k = 0; k < features[i].operations.size(); ++k) items.push_back({i, k, &features[i].operations[k]});
  }
  std::stable_sort(items.begin(), items.end(), [](const Item& a, const Item& b) {
    return std::make_tuple(static_cast<int>(a.op->phase), a.op->rank, a.op->tool->number, a.feature, a.index) <
           std::make_tuple(static_cast<int>(b.op->phase), b.op->rank, b.op->tool->number, b.feature, b.index);
  });

  // Tools by number; one technology per (tool, kind of cut).
  std::map<int, const setup::Tool*> used;
  for (const auto& item : items) used[item.op->tool->number] = item.op->tool;
  std::map<int, std::uint32_t> tool_index;
  for (const auto& [number, tool] : used) {
    tool_index[number] = static_cast<std::uint32_t>(p.tools.size());
    p.tools.push_back(tool_entity(*tool));
  }
  std::map<std::pair<int, int>, std::uint32_t> technology_index;
  std::map<std::string, int> names;
  for (const auto& item : items) {
    const auto& planned = *item.op;
    const auto key = std::make_pair(planned.tool->number, static_cast<int>(planned.cut));
    auto tech = technology_index.find(key);
    if (tech == technology_index.end()) {
      const CuttingData data = cutting_data(*planned.tool, planned.cut, options);
      sn::MillingTechnology t;
      t.feedrate = data.feed / 60000.0;
      t.spindle = -data.rpm / 60.0;  // clockwise (M3)
      p.technologies.push_back(t);
      tech = technology_index.emplace(key, static_cast<std::uint32_t>(p.technologies.size() - 1)).first;
    }
    sn::Operation op = planned.operation;
    auto& mop = sn::machining_operation(op);
    std::string id = planned.word + " " + features[item.feature].id;
    if (const int n = ++names[id]; n > 1) id += " " + std::to_string(n);
    mop.its_id = id;
    mop.its_tool = {tool_index.at(planned.tool->number)};
    mop.its_technology = {tech->second};
    mop.its_machine_functions = {0};
    p.operations.push_back(std::move(op));
    sn::MachiningWorkingstep ws;
    ws.its_id = "WS " + id;
    ws.its_secplane = secplane;
    ws.its_feature = {static_cast<std::uint32_t>(item.feature)};
    ws.its_operation = {static_cast<std::uint32_t>(p.operations.size() - 1)};
    p.main_workplan.its_elements.push_back(std::move(ws));
    out.features[item.feature].workingsteps.push_back(p.main_workplan.its_elements.size() - 1);
  }
}

}  // namespace ncbridge::process_planner
