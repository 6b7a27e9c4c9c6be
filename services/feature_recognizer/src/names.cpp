#include <string_view>

#include "ncbridge/feature_recognizer/feature.hpp"

namespace ncbridge::feature_recognizer {

bool RecognizedFeature::closed() const {
  switch (type) {
    case FeatureType::RoundHole:
    case FeatureType::ClosedPocket: return true;
    case FeatureType::Slot: return slot_ends[0] != SlotEnd::Open && slot_ends[1] != SlotEnd::Open;
    default: return false;
  }
}

std::string_view to_string(FeatureType type) {
  switch (type) {
    case FeatureType::PlanarFace: return "planar_face";
    case FeatureType::RoundHole: return "round_hole";
    case FeatureType::ClosedPocket: return "closed_pocket";
    case FeatureType::OpenPocket: return "open_pocket";
    case FeatureType::Slot: return "slot";
    case FeatureType::Step: return "step";
    case FeatureType::GeneralOutsideProfile: return "general_outside_profile";
    case FeatureType::Region: return "region";
  }
  return "region";
}

std::string_view to_string(OperationType type) {
  switch (type) {
    case OperationType::PlaneRoughMilling: return "plane_rough_milling";
    case OperationType::PlaneFinishMilling: return "plane_finish_milling";
    case OperationType::BottomAndSideRoughMilling: return "bottom_and_side_rough_milling";
    case OperationType::BottomAndSideFinishMilling: return "bottom_and_side_finish_milling";
    case OperationType::SideRoughMilling: return "side_rough_milling";
    case OperationType::SideFinishMilling: return "side_finish_milling";
    case OperationType::Drilling: return "drilling";
    case OperationType::MultistepDrilling: return "multistep_drilling";
    case OperationType::CenterDrilling: return "center_drilling";
    case OperationType::Reaming: return "reaming";
    case OperationType::BoringOperation: return "boring";
    case OperationType::Tapping: return "tapping";
    case OperationType::FreeformOperation: return "freeform_operation";
  }
  return "freeform_operation";
}

std::string_view to_string(Strategy strategy) {
  switch (strategy) {
    case Strategy::None: return "none";
    case Strategy::Unidirectional: return "unidirectional";
    case Strategy::Bidirectional: return "bidirectional";
    case Strategy::CenterMilling: return "center_milling";
    case Strategy::Contour: return "contour";
    case Strategy::ContourParallel: return "contour_parallel";
    case Strategy::ContourSpiral: return "contour_spiral";
    case Strategy::Adaptive: return "adaptive";
    case Strategy::Helical: return "helical";
    case Strategy::Plunge: return "plunge";
    case Strategy::BidirectionalContour: return "bidirectional_contour";
    case Strategy::ContourBidirectional: return "contour_bidirectional";
  }
  return "none";
}

std::string_view to_string(BottomCondition bottom) {
  switch (bottom) {
    case BottomCondition::None: return "none";
    case BottomCondition::Planar: return "planar";
    case BottomCondition::Conical: return "conical";
    case BottomCondition::Through: return "through";
    case BottomCondition::General: return "general";
  }
  return "none";
}

std::string_view to_string(OpenSide side) {
  switch (side) {
    case OpenSide::XMinus: return "x-";
    case OpenSide::XPlus: return "x+";
    case OpenSide::YMinus: return "y-";
    case OpenSide::YPlus: return "y+";
  }
  return "x-";
}

}  // namespace ncbridge::feature_recognizer
