// The solver's sub-commands of `limber`, one file each (modes, run, select); `render` and
// `report` come from render/ and report/. The struct and the exit codes are cli/command.h's.
#pragma once

#include <CLI/CLI.hpp>

#include "cli/command.h"

namespace limber::app {

using cli::Command;
using cli::kExitBadInput;
using cli::kExitInaccurate;
using cli::kExitInternal;
using cli::kExitInterrupted;
using cli::kExitNumerical;
using cli::kExitOk;

// `limber modes CASE [-o DIR] [--json] [--vtu-format ascii|binary]`.
Command add_modes_command(CLI::App& app);

// `limber select CASE [-o DIR] [--keep F] [--target E] [--json] ...` (select_command.cpp).
Command add_select_command(CLI::App& app);

// `limber sweep CASE --over AXES [-o DIR] [--reference tight|RESULTS] [--target E] [--json]`
// (sweep_command.cpp).
Command add_sweep_command(CLI::App& app);

// `limber run CASE [-o DIR] [--integrator ida|galpha] [--rtol R] [--atol A] [--step H]
// [--t-end T] [--start assembly|statics] [--json]`.
Command add_run_command(CLI::App& app);

// `limber statics CASE [-o DIR] [--json]` (statics_command.cpp).
Command add_statics_command(CLI::App& app);

// `limber linearize CASE [--statics | --at T] [--reference-body NAME] [-o DIR] [--json]`
// (linearize_command.cpp).
Command add_linearize_command(CLI::App& app);

}  // namespace limber::app
