// The ISO 14649 entity name of each model alternative, and access to the shared attributes.
#include <type_traits>

#include "ncbridge/stepnc/features.hpp"
#include "ncbridge/stepnc/operations.hpp"

namespace ncbridge::stepnc {

namespace {
template <class... F> struct Overload : F... { using F::operator()...; };
template <class... F> Overload(F...) -> Overload<F...>;
}  // namespace

const std::string& feature_id(const Feature& feature) {
  return std::visit(Overload{[](const Region& r) -> const std::string& { return r.its_id; },
                             [](const MachiningFeature& f) -> const std::string& { return f.its_id; }},
                    feature);
}

std::string_view entity_name(const Feature& feature) {
  return std::visit(Overload{
      [](const ToolpathFeature&) { return std::string_view("TOOLPATH_FEATURE"); },
      [](const RoundHole&) { return std::string_view("ROUND_HOLE"); },
      [](const PlanarFace&) { return std::string_view("PLANAR_FACE"); },
      [](const ClosedPocket&) { return std::string_view("CLOSED_POCKET"); },
      [](const OpenPocket&) { return std::string_view("OPEN_POCKET"); },
      [](const Slot&) { return std::string_view("SLOT"); },
      [](const Step&) { return std::string_view("STEP"); },
      [](const GeneralOutsideProfile&) { return std::string_view("GENERAL_OUTSIDE_PROFILE"); },
      [](const Region&) { return std::string_view("REGION"); }}, feature);
}

const MachiningOperation& machining_operation(const Operation& operation) {
  return std::visit([](const auto& op) -> const MachiningOperation& { return op; }, operation);
}

MachiningOperation& machining_operation(Operation& operation) {
  return std::visit([](auto& op) -> MachiningOperation& { return op; }, operation);
}

std::string_view entity_name(const Operation& operation) {
  return std::visit(Overload{
      [](const FreeformOperation&) { return std::string_view("FREEFORM_OPERATION"); },
      [](const Drilling&) { return std::string_view("DRILLING"); },
      [](const CenterDrilling&) { return std::string_view("CENTER_DRILLING"); },
      [](const MultistepDrilling&) { return std::string_view("MULTISTEP_DRILLING"); },
      [](const Boring&) { return std::string_view("BORING"); },
      [](const Reaming&) { return std::string_view("REAMING"); },
      [](const BackBoring&) { return std::string_view("BACK_BORING"); },
      [](const Tapping&) { return std::string_view("TAPPING"); },
      [](const PlaneRoughMilling&) { return std::string_view("PLANE_ROUGH_MILLING"); },
      [](const PlaneFinishMilling&) { return std::string_view("PLANE_FINISH_MILLING"); },
      [](const SideRoughMilling&) { return std::string_view("SIDE_ROUGH_MILLING"); },
      [](const SideFinishMilling&) { return std::string_view("SIDE_FINISH_MILLING"); },
      [](const BottomAndSideRoughMilling&) { return std::string_view("BOTTOM_AND_SIDE_ROUGH_MILLING"); },
      [](const BottomAndSideFinishMilling&) { return std::string_view("BOTTOM_AND_SIDE_FINISH_MILLING"); }},
      operation);
}

}  // namespace ncbridge::stepnc
