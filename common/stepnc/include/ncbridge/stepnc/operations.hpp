#pragma once
// Operations of ISO 14649-10/-11 (2002 drafts), with explicit toolpaths (TOOLPATH_LIST of
// CUTTER_LOCATION_TRAJECTORY). Structs mirror the EXPRESS inheritance: each level adds its own
// attributes in schema order, so the writer walks them in the order the file needs.
#include <cstdint>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "ncbridge/stepnc/geometry.hpp"
#include "ncbridge/stepnc/refs.hpp"

namespace ncbridge::stepnc {

enum class ToolpathType : std::uint8_t { Approach, Lift, Connect, NonContact, Contact, TrajectoryPath };

struct CutterLocationTrajectory {
  bool its_priority = true;
  ToolpathType its_type = ToolpathType::TrajectoryPath;
  std::optional<TechnologyRef> its_technology;
  std::optional<MachineFunctionsRef> its_machine_functions;
  std::optional<bool> its_direction;
  CompositeCurve basiccurve;  // tool centre point (tip) locations, mm
  friend bool operator==(const CutterLocationTrajectory&, const CutterLocationTrajectory&) = default;
};

struct ToolpathList {
  std::vector<CutterLocationTrajectory> its_list;  // at least one
  friend bool operator==(const ToolpathList&, const ToolpathList&) = default;
};

// OPERATION + MACHINING_OPERATION + MILLING_MACHINING_OPERATION attributes.
struct MachiningOperation {
  std::optional<ToolpathList> its_toolpath;
  std::string its_id;
  std::optional<double> retract_plane;  // above the feature placement, mm
  std::optional<CartesianPoint> start_point;
  ToolRef its_tool;
  TechnologyRef its_technology;
  MachineFunctionsRef its_machine_functions;
  std::optional<double> overcut_length;
  friend bool operator==(const MachiningOperation&, const MachiningOperation&) = default;
};

// ---- Milling (MILLING_TYPE_OPERATION: approach/retract strategies are not modelled: written $)
struct FreeformOperation : MachiningOperation {
  friend bool operator==(const FreeformOperation&, const FreeformOperation&) = default;
};

// TWO5D_MILLING_STRATEGY subtypes (CC2).
enum class CutmodeType : std::uint8_t { Climb, Conventional };
enum class RotDirection : std::uint8_t { Cw, Ccw };
enum class LeftOrRight : std::uint8_t { Left, Right };
// Each ends with TWO5D_MILLING_STRATEGY's own attributes: overlap (a ratio of the cutter's
// diameter shared by neighbouring passes) and allow_multiple_passes.
struct Unidirectional {
  std::optional<Direction> feed_direction; std::optional<CutmodeType> cutmode;
  std::optional<double> overlap; std::optional<bool> allow_multiple_passes;
  friend bool operator==(const Unidirectional&, const Unidirectional&) = default;
};
struct Bidirectional {
  std::optional<Direction> feed_direction; std::optional<LeftOrRight> stepover_direction;
  std::optional<double> overlap; std::optional<bool> allow_multiple_passes;
  friend bool operator==(const Bidirectional&, const Bidirectional&) = default;
};
struct ContourParallel {
  std::optional<RotDirection> rotation_direction; std::optional<CutmodeType> cutmode;
  std::optional<double> overlap; std::optional<bool> allow_multiple_passes;
  friend bool operator==(const ContourParallel&, const ContourParallel&) = default;
};
struct ContourSpiral {
  std::optional<RotDirection> rotation_direction; std::optional<CutmodeType> cutmode;
  std::optional<double> overlap; std::optional<bool> allow_multiple_passes;
  friend bool operator==(const ContourSpiral&, const ContourSpiral&) = default;
};
struct CenterMilling {
  std::optional<double> overlap; std::optional<bool> allow_multiple_passes;
  friend bool operator==(const CenterMilling&, const CenterMilling&) = default;
};
// Zigzag then one contour along the boundary (bidirectional_contour), or the contour first
// (contour_bidirectional).
struct BidirectionalContour {
  std::optional<Direction> feed_direction; std::optional<LeftOrRight> stepover_direction;
  std::optional<RotDirection> rotation_direction; std::optional<CutmodeType> spiral_cutmode;
  std::optional<double> overlap; std::optional<bool> allow_multiple_passes;
  friend bool operator==(const BidirectionalContour&, const BidirectionalContour&) = default;
};
struct ContourBidirectional {
  std::optional<Direction> feed_direction; std::optional<LeftOrRight> stepover_direction;
  std::optional<RotDirection> rotation_direction; std::optional<CutmodeType> spiral_cutmode;
  std::optional<double> overlap; std::optional<bool> allow_multiple_passes;
  friend bool operator==(const ContourBidirectional&, const ContourBidirectional&) = default;
};
using Two5DMillingStrategy = std::variant<Unidirectional, Bidirectional, ContourParallel, ContourSpiral, CenterMilling,
                                          BidirectionalContour, ContourBidirectional>;

struct Two5DMillingOperation : MachiningOperation {
  std::optional<Two5DMillingStrategy> its_machining_strategy;
  std::optional<double> axial_cutting_depth;
  std::optional<double> radial_cutting_depth;  // side and bottom-and-side milling only
  std::optional<double> allowance_side;        // side and bottom-and-side milling only
  std::optional<double> allowance_bottom;      // plane and bottom-and-side milling only
  friend bool operator==(const Two5DMillingOperation&, const Two5DMillingOperation&) = default;
};
struct PlaneRoughMilling : Two5DMillingOperation {};
struct PlaneFinishMilling : Two5DMillingOperation {};
struct SideRoughMilling : Two5DMillingOperation {};
struct SideFinishMilling : Two5DMillingOperation {};
struct BottomAndSideRoughMilling : Two5DMillingOperation {};
struct BottomAndSideFinishMilling : Two5DMillingOperation {};

// ---- Drilling family (DRILLING_TYPE_OPERATION)
struct DrillingTypeStrategy {
  std::optional<double> reduced_cut_at_start, reduced_feed_at_start, depth_of_start;
  std::optional<double> reduced_cut_at_end, reduced_feed_at_end, depth_of_end;
  friend bool operator==(const DrillingTypeStrategy&, const DrillingTypeStrategy&) = default;
};

struct DrillingTypeOperation : MachiningOperation {
  std::optional<double> cutting_depth;        // mm below the feature placement
  std::optional<double> previous_diameter;
  std::optional<double> dwell_time_bottom;    // s
  std::optional<double> feed_on_retract;      // ratio of the feed
  std::optional<DrillingTypeStrategy> its_machining_strategy;
  friend bool operator==(const DrillingTypeOperation&, const DrillingTypeOperation&) = default;
};

struct Drilling : DrillingTypeOperation {};
struct CenterDrilling : DrillingTypeOperation {};
struct MultistepDrilling : DrillingTypeOperation {
  double retract_distance = 0;
  double first_depth = 0;
  double depth_of_step = 0;
  std::optional<double> dwell_time_step;
  friend bool operator==(const MultistepDrilling&, const MultistepDrilling&) = default;
};
struct BoringOperation : DrillingTypeOperation {
  bool spindle_stop_at_bottom = false;
  std::optional<double> depth_of_testcut;
  std::optional<CartesianPoint> waiting_position;
  friend bool operator==(const BoringOperation&, const BoringOperation&) = default;
};
struct Boring : BoringOperation {};
struct Reaming : BoringOperation {};
struct BackBoring : DrillingTypeOperation {};
struct Tapping : DrillingTypeOperation {
  bool compensation_chuck = false;
  friend bool operator==(const Tapping&, const Tapping&) = default;
};

using Operation = std::variant<FreeformOperation, Drilling, CenterDrilling, MultistepDrilling,
                               Boring, Reaming, BackBoring, Tapping, PlaneRoughMilling,
                               PlaneFinishMilling, SideRoughMilling, SideFinishMilling,
                               BottomAndSideRoughMilling, BottomAndSideFinishMilling>;

const MachiningOperation& machining_operation(const Operation& operation);
MachiningOperation& machining_operation(Operation& operation);
std::string_view entity_name(const Operation& operation);  // "FREEFORM_OPERATION", ...

}  // namespace ncbridge::stepnc
