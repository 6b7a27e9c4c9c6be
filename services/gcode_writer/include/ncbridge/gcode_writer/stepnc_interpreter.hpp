#pragma once
// A STEP-NC "interpreter" (the role of NIST's, whose output for ISO 14649-11 example 1 is
// nist_ex1.can): a CC1 project (ncbridge::stepnc::Project, read from a Part 21 file or made in
// memory) -> canonical calls, which a ProgramWriter writes as a program (docs/gcode.md).
//
// The workplan's elements in order:
//  - a RAPID_MOVEMENT's toolpath as rapids (setup frame);
//  - a MACHINING_WORKINGSTEP whose operation has explicit toolpaths (CUTTER_LOCATION_TRAJECTORY):
//    its tool (a tool change with its length offset when it is not in the spindle), technology
//    (feed, spindle) and machine functions (coolant), a trajectory's own technology or functions
//    in force for it; CONNECT and NON_CONTACT trajectories as rapids, the others as feeds; lines
//    as straight moves, arcs as arcs (a helix within its chords). Toolpath points are in the
//    frame of the workingstep's feature placement (as NIST's interpreter reads them; the
//    TOOLPATH_FEATUREs ncbridge writes sit at the setup origin);
//  - a drilling-family operation on a ROUND_HOLE (no toolpath: its parameters describe the
//    motion) as a canned cycle at the hole: DRILLING/CENTER_DRILLING G81 (G82 with a dwell),
//    MULTISTEP_DRILLING G83 (G73 when it retracts less than a step), TAPPING G84 (G74 with the
//    spindle counter-clockwise), REAMING/BORING feeding out G85 (G89 with a dwell), BORING
//    stopping the spindle at the bottom G86, the others G81; the calls carry their CycleTag, the
//    tool retracts to the height it came from (G98);
//  - then M30.
// Where a trajectory does not start where the tool is, the tool goes there over the
// workingstep's security plane (up, across, down); the first move after a tool change goes
// straight to the start, as the program the file was converted from did.
//
// What the model cannot say as motion is an InputError naming the workingstep: an operation
// without toolpath that is not a drilling operation (CC2: it needs the toolpath generator), a
// back boring (G87 needs offsets the model does not keep), a feed move without a feed rate, a
// workingstep whose operation or tool is missing.
#include <string>

#include "ncbridge/canonical/call.hpp"
#include "ncbridge/setup/tool_list.hpp"
#include "ncbridge/stepnc/project.hpp"

namespace ncbridge::gcode_writer {

struct StepncOptions {
  enum class ToolpathFrame {
    Feature,  // toolpaths of a machining workingstep in its feature's placement (ISO 14649, NIST)
    Setup,    // in the setup frame whatever the feature (a generator that writes them so)
  };
  ToolpathFrame toolpath_frame = ToolpathFrame::Feature;
  // A COMMENT naming each workplan element before its calls.
  bool name_workingsteps = false;
};

// The tools of a project as the program's tool table: the T number of each tool (from its id
// "T<n> ..."; tools without one numbered after the highest, in the order of the table), its
// length (CUTTING_COMPONENT.tool_offset_length, G43 H) and diameter.
setup::ToolList stepnc_tools(const stepnc::Project& project);

// The calls of the project into `sink` (source_file(0, file_name), calls, end()). Calls name
// the workplan element they come from by its 1-based position (Source::line).
void interpret_stepnc(const stepnc::Project& project, const std::string& file_name, const StepncOptions& options,
                      canonical::Sink& sink);

}  // namespace ncbridge::gcode_writer
