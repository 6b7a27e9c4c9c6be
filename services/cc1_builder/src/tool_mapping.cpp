#include "tool_mapping.hpp"

#include <string>

namespace ncbridge::cc1_builder {

namespace {

stepnc::ToolBody body_of(setup::ToolType type) {
  using setup::ToolType;
  using stepnc::ToolBody;
  switch (type) {
    case ToolType::FaceMill: return ToolBody::Facemill;
    case ToolType::FlatEndMill: return ToolBody::Endmill;
    case ToolType::BallEndMill: return ToolBody::BallEndmill;
    case ToolType::BullNoseEndMill: return ToolBody::BullnoseEndmill;
    case ToolType::Drill: return ToolBody::TwistDrill;
    case ToolType::CenterDrill: case ToolType::SpotDrill: return ToolBody::Centerdrill;
    case ToolType::Reamer: return ToolBody::Reamer;
    case ToolType::Tap: return ToolBody::Tap;
    case ToolType::BoringBar: return ToolBody::BoringTool;
    case ToolType::TSlotMill: return ToolBody::TSlotMill;
    case ToolType::ChamferMill: return ToolBody::Countersink;
    case ToolType::Unknown: break;
  }
  return ToolBody::UserDefinedTool;
}

}  // namespace

stepnc::MillingCuttingTool milling_cutting_tool(const setup::Tool& tool) {
  stepnc::MillingCuttingTool t;
  t.number = tool.number;
  t.its_id = "T" + std::to_string(tool.number) + (tool.name.empty() ? "" : " " + tool.name);
  t.body = body_of(tool.type);
  t.dimension.diameter = tool.diameter;
  if (tool.point_angle > 0) t.dimension.tool_tip_half_angle = tool.point_angle / 2;
  if (tool.flute_length > 0) t.dimension.cutting_edge_length = tool.flute_length;
  switch (t.body) {
    case stepnc::ToolBody::BallEndmill:
      t.dimension.edge_radius = tool.diameter / 2;
      t.dimension.edge_center_vertical = tool.diameter / 2;
      t.dimension.edge_center_horizontal = 0.0;
      break;
    case stepnc::ToolBody::BullnoseEndmill:
    case stepnc::ToolBody::Endmill:
    case stepnc::ToolBody::Facemill:
      if (tool.corner_radius > 0) {
        t.dimension.edge_radius = tool.corner_radius;
        t.dimension.edge_center_vertical = tool.corner_radius;
        t.dimension.edge_center_horizontal = tool.diameter / 2 - tool.corner_radius;
      }
      break;
    default: break;
  }
  if (tool.flutes > 0) t.number_of_teeth = tool.flutes;
  t.tool_offset_length = tool.length;
  if (tool.length > 0) t.overall_assembly_length = tool.length;
  return t;
}

}  // namespace ncbridge::cc1_builder
