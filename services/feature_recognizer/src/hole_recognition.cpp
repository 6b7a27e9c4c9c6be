#include "hole_recognition.hpp"

#include <algorithm>
#include <cmath>

#include "box_index.hpp"

namespace ncbridge::feature_recognizer {

OperationType hole_operation_type(const setup::Tool& tool, const std::optional<canonical::CycleTag>& cycle,
                                  int passes) {
  using T = setup::ToolType;
  switch (tool.type) {
    case T::Reamer: return OperationType::Reaming;
    case T::Tap: return OperationType::Tapping;
    case T::BoringBar: return OperationType::BoringOperation;
    case T::CenterDrill:
    case T::SpotDrill: return OperationType::CenterDrilling;
    default: break;
  }
  if (cycle) {
    switch (cycle->g_code_x10) {
      case 730:
      case 830: return OperationType::MultistepDrilling;
      case 840:
      case 841: return OperationType::Tapping;
      case 850:
      case 890: return OperationType::Reaming;
      case 760:
      case 860:
      case 870:
      case 880: return OperationType::BoringOperation;
      default: break;
    }
  }
  // A drilling cycle that is not a peck cycle drills, even when repeated deeper (G81 at three
  // depths, as in Xú et al.'s test part); uncycled descents in one workingstep are pecks.
  if (cycle) return OperationType::Drilling;
  return passes > 1 ? OperationType::MultistepDrilling : OperationType::Drilling;
}

std::vector<HoleCandidate> recognize_holes(const std::vector<DrillPass>& passes) {
  struct Cluster {
    Point2 at;
    std::vector<const DrillPass*> passes;
  };
  std::vector<Cluster> clusters;
  BoxIndex index(25.0);  // clusters by place: a pass meets the few near it, not every one
  for (const auto& pass : passes) {
    Cluster* found = nullptr;
    const Box2 near{pass.at.x - kSameHoleDistance, pass.at.y - kSameHoleDistance, pass.at.x + kSameHoleDistance,
                    pass.at.y + kSameHoleDistance};
    for (auto i : index.candidates(near)) {
      auto& c = clusters[i];
      if (std::hypot(c.at.x - pass.at.x, c.at.y - pass.at.y) < kSameHoleDistance) found = &c;
    }
    if (!found) {
      clusters.push_back({pass.at, {}});
      index.insert(clusters.size() - 1, {pass.at.x, pass.at.y, pass.at.x, pass.at.y});
      found = &clusters.back();
    }
    found->passes.push_back(&pass);
  }

  std::vector<HoleCandidate> holes;
  for (const auto& c : clusters) {
    HoleCandidate hole;
    hole.at = c.at;
    hole.first_workingstep = c.passes.front()->workingstep;
    hole.sequence = c.passes.front()->sequence;
    hole.z_bottom = c.passes.front()->z_bottom;
    // The hole's diameter is what drills, reamers and boring bars make: a spot or centre drill
    // chamfers the edge and a tap cuts a thread (often larger), unless nothing else cut the hole.
    auto sizes_hole = [](setup::ToolType t) {
      return t != setup::ToolType::SpotDrill && t != setup::ToolType::CenterDrill && t != setup::ToolType::Tap;
    };
    const bool any_sizing = std::any_of(c.passes.begin(), c.passes.end(), [&](const DrillPass* p) { return sizes_hole(p->tool.type); });
    for (const auto* p : c.passes) {
      if (!any_sizing || sizes_hole(p->tool.type)) hole.diameter = std::max(hole.diameter, p->tool.diameter);
      if (p->z_bottom <= hole.z_bottom) {
        hole.z_bottom = p->z_bottom;
        hole.point_angle = is_hole_making_tool(p->tool.type) ? p->tool.point_angle : 0;
      }
    }
    // One operation per run of passes with the same tool and workingstep sequence.
    std::vector<std::vector<const DrillPass*>> runs;
    for (const auto* p : c.passes) {
      if (runs.empty() || runs.back().back()->tool.number != p->tool.number) runs.emplace_back();
      runs.back().push_back(p);
    }
    for (const auto& run : runs) {
      RecognizedOperation op;
      const auto* first = run.front();
      // Pecks: more than one descending pass of one cycle, or of one uncycled workingstep.
      // Uncycled, a peck starts its feed down in the hole (the tool rapids back in); a descent
      // fed again from the first one's start is the hole drilled again, deeper.
      int descents = 0;
      for (const auto* p : run) {
        const bool peck = p == first || p->cycle || p->z_top < first->z_top - 0.01;
        if (peck && (!p->cycle || !first->cycle || p->cycle->cycle_id == first->cycle->cycle_id)) ++descents;
      }
      op.type = hole_operation_type(first->tool, first->cycle, descents);
      op.strategy = Strategy::Plunge;
      op.tool_number = first->tool.number;
      op.layers = static_cast<int>(run.size());
      op.feed = first->feed;
      op.spindle_rpm = first->spindle_rpm;
      double previous = run.front()->z_top;
      double step = 0;
      for (const auto* p : run) {
        if (op.workingsteps.empty() || op.workingsteps.back() != p->workingstep) op.workingsteps.push_back(p->workingstep);
        step = std::max(step, previous - p->z_bottom);
        previous = p->z_bottom;
      }
      op.axial_depth = run.size() > 1 ? step : 0;
      hole.operations.push_back(std::move(op));
    }
    holes.push_back(std::move(hole));
  }
  return holes;
}

}  // namespace ncbridge::feature_recognizer
