#pragma once
// The ISO 14649-10 project: PROJECT -> WORKPLAN -> executables (MACHINING_WORKINGSTEP,
// RAPID_MOVEMENT, WORKPIECE_PROBING), WORKPIECE (with its rawpiece), SETUP, and the tables the executables refer
// to by index. One value holds a whole CC1 or CC2 program; the step_writer maps it to Part 21
// and back (stepnc_file.hpp).
#include <cstdint>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "ncbridge/stepnc/features.hpp"
#include "ncbridge/stepnc/geometry.hpp"
#include "ncbridge/stepnc/operations.hpp"
#include "ncbridge/stepnc/refs.hpp"
#include "ncbridge/stepnc/resources.hpp"

namespace ncbridge::stepnc {

// Program lines a workingstep came from (not a schema attribute; empty after reading a file).
struct SourceLines {
  std::uint32_t file = 0;
  std::uint32_t first_line = 0;
  std::uint32_t last_line = 0;
  friend bool operator==(const SourceLines&, const SourceLines&) = default;
};

struct MachiningWorkingstep {
  std::string its_id;
  Plane its_secplane;
  FeatureRef its_feature;
  OperationRef its_operation;
  SourceLines source;
  friend bool operator==(const MachiningWorkingstep&, const MachiningWorkingstep&) = default;
};

struct RapidMovement {
  std::string its_id;
  Plane its_secplane;
  std::optional<ToolpathList> its_toolpath;
  SourceLines source;
  friend bool operator==(const RapidMovement&, const RapidMovement&) = default;
};

// NC_VARIABLE: a variable of the controller, by name (its initial value when known).
struct NcVariable {
  std::string its_name;
  std::optional<double> initial_value;
  friend bool operator==(const NcVariable&, const NcVariable&) = default;
};

// WORKPIECE_PROBING (ISO 14649-10 touch probing, a workingstep and operation of its own): the
// probe TOUCH_PROBE(its_probe) starts at start_position, moves along its_direction and is
// expected to touch the workpiece (the project's) within expected_value; the result goes to
// measured_offset. its_toolpath and its_tool_direction are not used ($).
struct WorkpieceProbing {
  std::string its_id;
  Plane its_secplane;
  NcVariable measured_offset;
  Axis2Placement3d start_position;
  Direction its_direction;
  TolerancedLengthMeasure expected_value;
  std::string its_probe;  // TOUCH_PROBE.its_id
  SourceLines source;
  friend bool operator==(const WorkpieceProbing&, const WorkpieceProbing&) = default;
};

using Executable = std::variant<MachiningWorkingstep, RapidMovement, WorkpieceProbing>;

struct Workplan {
  std::string its_id = "MAIN WORKPLAN";
  std::vector<Executable> its_elements;  // its_setup is the project's setup
  friend bool operator==(const Workplan&, const Workplan&) = default;
};

struct Workpiece {
  std::string its_id;
  std::optional<double> global_tolerance;
  std::optional<Block> its_bounding_geometry;
  std::vector<CartesianPoint> clamping_positions;
  friend bool operator==(const Workpiece&, const Workpiece&) = default;
};

struct WorkpieceSetup {
  Axis2Placement3d its_origin;  // the workpiece in the setup frame
  friend bool operator==(const WorkpieceSetup&, const WorkpieceSetup&) = default;
};

struct Setup {
  std::string its_id = "SETUP1";
  std::optional<Axis2Placement3d> its_origin;  // the work offset (G54...) in machine coordinates
  Plane its_secplane;
  WorkpieceSetup its_workpiece_setup;
  friend bool operator==(const Setup&, const Setup&) = default;
};

struct Project {
  std::string its_id;
  Workplan main_workplan;
  Workpiece workpiece;                 // the part
  std::optional<Workpiece> rawpiece;   // the stock (WORKPIECE.its_rawpiece of the part)
  Setup setup;
  std::vector<MillingCuttingTool> tools;
  std::vector<MillingTechnology> technologies;
  std::vector<MillingMachineFunctions> machine_functions;
  std::vector<Feature> features;
  std::vector<Operation> operations;
  friend bool operator==(const Project&, const Project&) = default;

  const MillingCuttingTool& tool(ToolRef r) const { return tools.at(r.index); }
  const MillingTechnology& technology(TechnologyRef r) const { return technologies.at(r.index); }
  const MillingMachineFunctions& functions(MachineFunctionsRef r) const { return machine_functions.at(r.index); }
  const Feature& feature(FeatureRef r) const { return features.at(r.index); }
  const Operation& operation(OperationRef r) const { return operations.at(r.index); }
};

}  // namespace ncbridge::stepnc
