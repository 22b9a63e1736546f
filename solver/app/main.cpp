// `limber`: dynamics of mechanisms with flexible parts. Entry point: parses the command
// line, runs the chosen sub-command, and maps errors to exit codes (command.h).
#include <CLI/CLI.hpp>
#include <cstdio>
#include <exception>
#include <vector>

#include "app/command.h"
#include "cli/help_wrap.h"
#include "core/error.h"
#include "modal/blas_threads.h"
#include "render_command.h"
#include "report_command.h"

int main(int argc, char** argv) {
  using namespace limber::app;
  // A process-wide setting, the program's to choose: one BLAS thread (modal/blas_threads.h).
  limber::modal::use_single_threaded_blas();
  CLI::App app{"limber " LIMBER_VERSION
               " - dynamics of mechanisms with flexible parts\n"
               "(component mode synthesis on a floating frame of reference)",
               "limber"};
  app.set_version_flag("--version", "limber " LIMBER_VERSION);
  app.require_subcommand(1);
  app.footer(
      "Exit codes: 0 success, 1 bad input (case file or command line), 2 numerical failure,\n"
      "3 internal error, 4 interrupted by a signal, 5 finished but not accurate (limber run).\n"
      "Case file format: docs/case-format.md.\n"
      "Run 'limber <command> --help' for the options of a command.");

  // Every sub-command registers itself; exactly one is run.
  const std::vector<Command> commands = {
      add_modes_command(app),
      add_run_command(app),
      add_statics_command(app),
      add_linearize_command(app),
      add_select_command(app),
      add_sweep_command(app),
      limber::render::add_render_command(app),
      limber::report::add_report_command(app),
  };
  // Every option's help within 100 columns (CLI11 does not wrap it).
  limber::cli::wrap_option_help(app);
  for (const Command& command : commands) limber::cli::wrap_option_help(*command.cli);

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    const int code = app.exit(error);
    return code == 0 ? kExitOk : kExitBadInput;
  }

  try {
    for (const Command& command : commands) {
      if (command.cli->parsed()) return command.run();
    }
  } catch (const limber::InputError& error) {
    std::fprintf(stderr, "limber: error: %s\n", error.what());
    return kExitBadInput;
  } catch (const limber::NumericalError& error) {
    std::fprintf(stderr, "limber: error: %s\n", error.what());
    return kExitNumerical;
  } catch (const std::exception& error) {
    std::fprintf(stderr, "limber: internal error: %s\n", error.what());
    return kExitInternal;
  }
  return kExitInternal;
}
