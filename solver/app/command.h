// The sub-commands of `limber`, one file each (modes_command.cpp, later run, render,
// report, select). Each adds itself to the CLI11 app and returns what to run when the
// user picked it; main.cpp dispatches and turns errors into exit codes.
#pragma once

#include <CLI/CLI.hpp>
#include <functional>

namespace limber::app {

// Exit codes of every sub-command.
inline constexpr int kExitOk = 0;
inline constexpr int kExitBadInput = 1;   // bad case file or command line (InputError)
inline constexpr int kExitNumerical = 2;  // a numerical method failed (e.g. eigen-solver)
inline constexpr int kExitInternal = 3;   // unexpected error: a bug, please report
inline constexpr int kExitInterrupted = 4;  // stopped by SIGINT or SIGTERM, files closed
inline constexpr int kExitInaccurate = 5;   // finished, but its own accuracy estimate says it is off

struct Command {
  CLI::App* cli = nullptr;   // the sub-command, parsed by main
  std::function<int()> run;  // returns an exit code; may throw InputError
};

// `limber modes CASE [-o DIR] [--json] [--vtu-format ascii|binary]`.
Command add_modes_command(CLI::App& app);

// `limber select CASE [-o DIR] [--keep F] [--target E] [--json] ...` (select_command.cpp).
Command add_select_command(CLI::App& app);

// `limber run CASE [-o DIR] [--integrator ida|galpha] [--rtol R] [--atol A] [--step H]
// [--t-end T] [--json]`.
Command add_run_command(CLI::App& app);

}  // namespace limber::app
