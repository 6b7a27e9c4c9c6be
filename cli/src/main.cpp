// ncbridge: CNC part programs to STEP-NC (ISO 14649) and back. See README.md and docs/cli.md.
#include <CLI/CLI.hpp>

#include <cstdio>
#include <exception>

#include "commands.hpp"
#include "ncbridge/common/error.hpp"

int main(int argc, char** argv) {
  CLI::App app{"ncbridge: CNC part programs to STEP-NC (ISO 14649) and back", "ncbridge"};
  app.set_version_flag("--version", "ncbridge " NCBRIDGE_VERSION);
  app.require_subcommand(1);
  int exit_code = 0;
  ncbridge::cli::add_canon_command(app, exit_code);
  ncbridge::cli::add_check_command(app, exit_code);
  ncbridge::cli::add_convert_command(app, exit_code);
  ncbridge::cli::add_diff_command(app, exit_code);
  ncbridge::cli::add_optimize_command(app, exit_code);
#ifdef NCBRIDGE_HAVE_SERVICES
  ncbridge::cli::add_up_command(app, exit_code);
  ncbridge::cli::add_submit_command(app, exit_code);
  ncbridge::cli::add_status_command(app, exit_code);
  ncbridge::cli::add_controller_sim_command(app, exit_code);
#endif
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  } catch (const ncbridge::InputError& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "ncbridge: error: %s\n", e.what());
    return 1;
  }
  return exit_code;
}
