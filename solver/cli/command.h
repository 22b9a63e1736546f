// One sub-command of `limber`, as every part that contributes one registers it: the solver's
// (solver/app), render/ and report/. Each adds itself to the CLI11 app and returns what to run
// when the user picked it; solver/app/main.cpp dispatches and turns errors into exit codes.
// Header-only (limber_cli): it needs CLI11 and <functional> and nothing of limber, so render/
// and report/ register their sub-commands without seeing solver/app.
#pragma once

#include <CLI/CLI.hpp>
#include <functional>

namespace limber::cli {

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

}  // namespace limber::cli
