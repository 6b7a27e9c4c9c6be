// ncbridge: CNC part programs to STEP-NC (ISO 14649) and back. See README.md and docs/cli.md.
#include <CLI/CLI.hpp>

#include <cstdio>
#include <exception>

#include "commands.hpp"
#include "errors.hpp"
#include "ncbridge/common/version.hpp"
#include "usage_errors.hpp"
#ifdef NCBRIDGE_HAVE_SERVICES
#include "ncbridge/bus/bus_error.hpp"
#endif

int main(int argc, char** argv) {
  using namespace ncbridge::cli;
  CLI::App app{"ncbridge: CNC part programs to STEP-NC (ISO 14649) and back", "ncbridge"};
  app.set_version_flag("--version", std::string(ncbridge::version_string()));
  app.require_subcommand(1);
  // -q/-v before or after the command's name (feedback.hpp).
  app.add_flag("-q,--quiet")->description("Say nothing but warnings and errors: no progress, no summary");
  app.add_flag("-v,--verbose")->description("Say more: what was read, each phase's time, what was written");
  app.fallthrough();
  app.footer("Exit status: 0 ok, 1 input error, 2 usage error, 3 output error, 4 service unavailable, "
             "5 files differ (diff). See docs/cli.md.");
  int exit_code = 0;
  add_canon_command(app, exit_code);
  add_check_command(app, exit_code);
  add_convert_command(app, exit_code);
  add_diff_command(app, exit_code);
  add_gcode_command(app, exit_code);
  add_plan_command(app, exit_code);
  add_optimize_command(app, exit_code);
#ifdef NCBRIDGE_HAVE_SERVICES
  add_up_command(app, exit_code);
  add_down_command(app, exit_code);
  add_submit_command(app, exit_code);
  add_status_command(app, exit_code);
  add_fetch_command(app, exit_code);
  add_cancel_command(app, exit_code);
  add_controller_sim_command(app, exit_code);
  add_capture_command(app, exit_code);
#endif
  if (const auto error = command_error(app, argc, argv)) {
    print_error(*error);
    return exit_status::usage_error;
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& e) {  // --help, --version
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    print_error(parse_error_message(app, e, argc, argv));
    return exit_status::usage_error;
#ifdef NCBRIDGE_HAVE_SERVICES
  } catch (const ncbridge::bus::BusError& e) {
    print_error(std::string("the DDS bus: ") + e.what());
    return exit_status::service_unavailable;
#endif
  } catch (...) {
    return report_exception(std::current_exception());
  }
  return exit_code;
}
