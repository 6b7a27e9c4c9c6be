#pragma once
// Each `ncbridge` subcommand lives in its own file and registers itself here.
namespace CLI { class App; }

namespace ncbridge::cli {

// Adds the subcommand to `app`; the callback it installs runs the command and sets the exit code.
void add_canon_command(CLI::App& app, int& exit_code);
void add_check_command(CLI::App& app, int& exit_code);  // Part 21 schema check (step_writer)
void add_convert_command(CLI::App& app, int& exit_code);  // program -> CC1 file (embedded pipeline)
void add_diff_command(CLI::App& app, int& exit_code);  // semantic Part 21 comparison (step_writer)
void add_gcode_command(CLI::App& app, int& exit_code);  // program or CC1 file -> program (gcode_writer)
void add_plan_command(CLI::App& app, int& exit_code);  // STEP part -> CC2 (part_reader, process_planner)
void add_optimize_command(CLI::App& app, int& exit_code);  // arcs, merged lines, loops (toolpath_optimizer)
// The DDS services (NCBRIDGE_BUILD_SERVICES): run them locally, submit jobs, list, live capture.
void add_up_command(CLI::App& app, int& exit_code);
void add_submit_command(CLI::App& app, int& exit_code);
void add_status_command(CLI::App& app, int& exit_code);
void add_controller_sim_command(CLI::App& app, int& exit_code);
void add_capture_command(CLI::App& app, int& exit_code);  // live capture from LinuxCNC, MTConnect
void add_down_command(CLI::App& app, int& exit_code);     // stops `up` (up_registry.hpp)
void add_fetch_command(CLI::App& app, int& exit_code);    // a submitted job's file, later
void add_cancel_command(CLI::App& app, int& exit_code);

}  // namespace ncbridge::cli
