#pragma once
// The tools a program uses: the project's JSON/YAML tool list (docs/formats/tools.md) or a
// LinuxCNC tool table. Lengths are stored in millimetres whatever the file's units.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "ncbridge/setup/length_units.hpp"

namespace ncbridge::setup {

// Tool kinds, named as in the tool list format and mapped to ISO 14649-111 tool entities.
enum class ToolType : std::uint8_t {
  Unknown, FaceMill, FlatEndMill, BallEndMill, BullNoseEndMill, Drill, CenterDrill, SpotDrill,
  Reamer, Tap, BoringBar, TSlotMill, ChamferMill
};
std::string_view to_string(ToolType type);           // "flat_end_mill", ...
std::optional<ToolType> tool_type_from_string(std::string_view name);

struct Tool {
  int number = 0;                 // T word
  std::string name;               // free text; empty if none
  ToolType type = ToolType::Unknown;
  double diameter = 0;            // mm
  double length = 0;              // mm, gauge length = tool length offset for G43
  double corner_radius = 0;       // mm
  double flute_length = 0;        // mm, 0 = unknown
  int flutes = 0;                 // 0 = unknown
  double point_angle = 0;         // degrees (drills), 0 = unknown
  double thread_pitch = 0;        // mm (taps), 0 = unknown
  // Cutting data the shop gives with the tool (0 = not given): spindle speed, feed and plunge
  // (axial) feed.
  double spindle_rpm = 0;         // rev/min
  double feed = 0;                // mm/min
  double plunge_feed = 0;         // mm/min
  // LinuxCNC tool-table extras (offsets beyond Z, orientation for lathes) are kept here.
  double x_offset = 0;            // mm
  int pocket = 0;                 // P in a tool table; defaults to the tool number
  int listed = 0;                 // 1-based position in its file (LinuxCNC's tool-table index)
};

class ToolList {
 public:
  ToolList() = default;
  explicit ToolList(std::vector<Tool> tools);

  const Tool* find(int number) const;          // nullptr if absent
  const std::vector<Tool>& tools() const { return tools_; }
  bool empty() const { return tools_.empty(); }

 private:
  std::vector<Tool> tools_;  // sorted by number, unique numbers
};

// The project's tool list: a JSON array (or {"tools": [...], "units": "mm"|"inch"}) or the same
// in YAML. Unknown fields are ignored. Errors (missing number, wrong type, unknown tool type,
// duplicate number) throw InputError with file and line. Other tools' data is read too:
// read_tool_list takes a FreeCAD tool library (.fctl) or bit (.fctb); both take a Fusion 360
// tool library's JSON export and a FreeCAD bit by their content (freecad_tools.hpp,
// fusion_tools.hpp).
ToolList read_tool_list(const std::filesystem::path& file);
ToolList parse_tool_list(std::string_view text, const std::string& file_name_for_errors);

// A LinuxCNC tool table (`T1 P1 D6.0 Z50.0 ;comment`), values in `units`. Lines it cannot
// read throw InputError (LinuxCNC silently ignores a bad table; we do not).
ToolList read_linuxcnc_tool_table(const std::filesystem::path& file, LengthUnits units);
ToolList parse_linuxcnc_tool_table(std::string_view text, LengthUnits units,
                                   const std::string& file_name_for_errors);

}  // namespace ncbridge::setup
