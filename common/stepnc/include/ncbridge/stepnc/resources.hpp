#pragma once
// Tools, technology and machine functions of ISO 14649-10/-11/-111 (2002 drafts), as values.
// Units as in the files: lengths mm, angles degrees, feed m/s, spindle rev/s, time s.
#include <cstdint>
#include <optional>
#include <string>

namespace ncbridge::stepnc {

// The MILLING_MACHINE_TOOL_BODY subtypes (ISO 14649-111 draft) a milling program's tools map to.
enum class ToolBody : std::uint8_t {
  Facemill, Endmill, BallEndmill, BullnoseEndmill, TSlotMill, TwistDrill, Centerdrill,
  Countersink, Reamer, Tap, BoringTool, UserDefinedTool
};

enum class Hand : std::uint8_t { Left, Right, Neutral };

struct MillingToolDimension {
  double diameter = 0;
  std::optional<double> tool_tip_half_angle;
  std::optional<double> tool_circumference_angle;
  std::optional<double> cutting_edge_length;
  std::optional<double> edge_radius;
  std::optional<double> edge_center_vertical;
  std::optional<double> edge_center_horizontal;
  friend bool operator==(const MillingToolDimension&, const MillingToolDimension&) = default;
};

// MILLING_CUTTING_TOOL with its tool body and one CUTTING_COMPONENT.
struct MillingCuttingTool {
  std::string its_id;                       // "T<number> <name>"; the reader recovers the number
  int number = 0;                           // the program's T word (not a schema attribute)
  ToolBody body = ToolBody::UserDefinedTool;
  MillingToolDimension dimension;
  std::optional<std::int64_t> number_of_teeth;
  std::optional<Hand> hand_of_cut;
  std::optional<bool> coolant_through_tool;
  std::optional<double> pilot_length;
  double tool_offset_length = 0;            // CUTTING_COMPONENT.tool_offset_length
  std::optional<double> overall_assembly_length;
  friend bool operator==(const MillingCuttingTool&, const MillingCuttingTool&) = default;
};

enum class ToolReferencePoint : std::uint8_t { Tcp, Ccp };

// MILLING_TECHNOLOGY: feedrate in m/s; spindle in rev/s, negative = clockwise (M3), positive =
// counter-clockwise (M4), 0 = stopped.
struct MillingTechnology {
  std::optional<double> feedrate;
  ToolReferencePoint feedrate_reference = ToolReferencePoint::Tcp;
  std::optional<double> cutspeed;
  std::optional<double> spindle;
  std::optional<double> feedrate_per_tooth;
  bool synchronize_spindle_with_feed = false;
  bool inhibit_feedrate_override = false;
  bool inhibit_spindle_override = false;
  friend bool operator==(const MillingTechnology&, const MillingTechnology&) = default;
};

// MILLING_MACHINE_FUNCTIONS: coolant = flood (M8), mist (M7).
struct MillingMachineFunctions {
  bool coolant = false;
  std::optional<double> coolant_pressure;
  std::optional<bool> mist;
  bool through_spindle_coolant = false;
  std::optional<double> through_pressure;
  bool chip_removal = false;
  friend bool operator==(const MillingMachineFunctions&, const MillingMachineFunctions&) = default;
};

}  // namespace ncbridge::stepnc
