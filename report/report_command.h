// The `limber report DIR... [-o OUT] [--title TEXT]` sub-command (CLI11), docs/report.md.
#pragma once

#include <CLI/CLI.hpp>

#include "cli/command.h"

namespace limber::report {

// Adds `report` to `app`. `run` writes the report, prints the path of index.html and returns
// cli::kExitOk; it throws InputError for a directory without readable results.
cli::Command add_report_command(CLI::App& app);

}  // namespace limber::report
