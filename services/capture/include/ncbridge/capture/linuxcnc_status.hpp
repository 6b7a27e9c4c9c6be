#pragma once
// LinuxCNC: `ncbridge capture linuxcnc` runs linuxcnc_status.py (compiled in) with the
// controller's Python; it writes one JSON line whenever the controller's status changes. Why
// the Python module: it reads the status buffer the GUIs read (no NML command, no TCP server
// to configure, any GUI can stay), and it ships with every LinuxCNC (docs/deployment.md).
#include <string>
#include <string_view>

#include "ncbridge/capture/run_tracker.hpp"

namespace ncbridge::capture {

// The status reader's source text.
std::string_view linuxcnc_status_script();

struct LinuxcncRecord {
  enum class Kind { Sample, Tools, Lost, Fatal };
  Kind kind = Kind::Sample;
  ControllerSample sample;      // Sample
  std::string tool_table;       // Tools: the loaded table, LinuxCNC .tbl lines
  bool inch = false;            // Tools: its lengths are in inches
  std::string reason;           // Lost, Fatal
};

// One line of the status reader; throws InputError (file "<linuxcnc status>") on a malformed one.
LinuxcncRecord parse_linuxcnc_status_line(std::string_view line);

}  // namespace ncbridge::capture
