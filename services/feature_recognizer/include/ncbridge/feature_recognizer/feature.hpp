#pragma once
// The recogniser's output: ISO 14649-10 manufacturing features (CC2) with the operations that
// cut them and the indices of the input workingsteps each operation is made of.
#include <array>
#include <cstdint>
#include <string_view>
#include <vector>

namespace ncbridge::feature_recognizer {

enum class FeatureType : std::uint8_t {
  PlanarFace, RoundHole, ClosedPocket, OpenPocket, Slot, Step, GeneralOutsideProfile, Region
};

enum class BottomCondition : std::uint8_t {
  None,      // not applicable (faces, outside profiles, steps)
  Planar,    // flat_hole_bottom / planar_pocket_bottom_condition
  Conical,   // conical_hole_bottom from the drill's point
  Through,   // through_bottom_condition
  General    // a 3D region: left as machined
};

enum class ProfileShape : std::uint8_t {
  None, Rectangular, Circular, GeneralClosed, Linear
};

struct Point2 {
  double x = 0, y = 0;
  friend bool operator==(const Point2&, const Point2&) = default;
};

// The feature's cross-section in its placement (ISO 14649 rectangular_closed_profile,
// circular_closed_profile, general_closed_profile; linear_profile for faces and steps).
struct Profile {
  ProfileShape shape = ProfileShape::None;
  double length = 0;        // along the placement's x direction (the longer side)
  double width = 0;
  double corner_radius = 0;
  double angle_deg = 0;     // rotation of `length` from the program's +X, in [0, 180)
  double diameter = 0;      // Circular
  std::vector<Point2> outline;  // GeneralClosed (and every closed region): the boundary, CCW
};

enum class OpenSide : std::uint8_t { XMinus, XPlus, YMinus, YPlus };

enum class SlotEnd : std::uint8_t { Open, Radiused, Flat };

enum class OperationType : std::uint8_t {
  PlaneRoughMilling, PlaneFinishMilling,
  BottomAndSideRoughMilling, BottomAndSideFinishMilling,
  SideRoughMilling, SideFinishMilling,
  Drilling, MultistepDrilling, CenterDrilling, Reaming, BoringOperation, Tapping,
  FreeformOperation
};

// ISO 14649-11 two5D_milling_strategy subtypes, plus the tool-path patterns CAM adds.
enum class Strategy : std::uint8_t {
  None, Unidirectional, Bidirectional, CenterMilling, Contour, ContourParallel,
  ContourSpiral, Adaptive, Helical, Plunge
};

struct RecognizedOperation {
  OperationType type = OperationType::BottomAndSideRoughMilling;
  Strategy strategy = Strategy::None;
  int tool_number = 0;
  std::vector<std::size_t> workingsteps;  // indices into the input, ascending
  double axial_depth = 0;        // depth of cut per layer (mm), 0 = one layer
  double radial_depth = 0;       // stepover (mm), 0 = unknown / not applicable
  double side_allowance = 0;     // material left on the walls for a later operation
  double bottom_allowance = 0;   // material left on the floor for a later operation
  int layers = 0;
  double feed = 0;
  double spindle_rpm = 0;
};

struct RecognizedFeature {
  FeatureType type = FeatureType::Region;
  // Placement: the centre of the feature's extent in XY at its top (ISO: the feature's
  // placement origin; its depth plane is bottom_z).
  double x = 0, y = 0;
  double top_z = 0, bottom_z = 0;
  double depth() const { return top_z - bottom_z; }
  double diameter = 0;                   // RoundHole
  Profile profile;
  BottomCondition bottom = BottomCondition::None;
  double bottom_angle_deg = 0;           // Conical: the drill's point angle
  std::vector<OpenSide> open_sides;      // for open features, which sides of the part it opens to
  std::array<SlotEnd, 2> slot_ends{SlotEnd::Open, SlotEnd::Open};  // Slot
  double slot_width = 0;                 // Slot
  std::vector<Point2> slot_course;       // Slot: its centre line (two points for a straight slot)
  std::vector<RecognizedOperation> operations;  // in machining order
  // Made beyond the recogniser's work limit (Options::work_per_point): a `region` of cuts not
  // analysed (its box, levels and operations), or a feature whose top or context was not
  // computed exactly (docs/recognition.md, "Bounded cost").
  bool approximate = false;

  bool closed() const;  // holes, closed pockets and slots with no open end
};

std::string_view to_string(FeatureType type);      // ISO 14649 entity name, lower case
std::string_view to_string(OperationType type);
std::string_view to_string(Strategy strategy);
std::string_view to_string(BottomCondition bottom);
std::string_view to_string(OpenSide side);

}  // namespace ncbridge::feature_recognizer
