// The `limber report DIR... [-o OUT] [--title TEXT]` sub-command (CLI11), docs/report.md.
// Same shape as solver/app/command.h's Command, defined here so report/ does not depend on the
// solver's application code.
#pragma once

#include <CLI/CLI.hpp>

#include <functional>

namespace limber::report {

struct ReportCommand {
  CLI::App* cli = nullptr;   // the sub-command, parsed by main
  std::function<int()> run;  // writes the report, prints the path of index.html, returns 0;
                             // throws InputError for a directory without readable results
};

// Adds `report` to `app`.
ReportCommand add_report_command(CLI::App& app);

}  // namespace limber::report
