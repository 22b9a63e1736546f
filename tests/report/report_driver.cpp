// Test driver for `limber report` until main.cpp registers the sub-command:
//   limber_report_driver scene DIR              writes the render test scene to DIR
//   limber_report_driver reactions DIR [A [NS]] writes a reaction run (amplitude A [N], NS
//                                               samples: long runs for the interactive plots)
//   limber_report_driver report DIR... [opts]   runs the sub-command as `limber report`
#include "core/error.h"
#include "reaction_runs.h"
#include "report_command.h"
#include "test_results.h"

#include <cstdio>
#include <string>

int main(int argc, char** argv) {
  const std::string what = argc > 1 ? argv[1] : "";
  if (what == "scene" && argc == 3) {
    limber::render::testing::write_test_results(argv[2], {});
    return 0;
  }
  if (what == "reactions" && argc >= 3 && argc <= 5) {
    limber::report::testing::ReactionRun run;
    if (argc >= 4) run.amplitude = std::stod(argv[3]);
    if (argc == 5) run.samples = std::stoi(argv[4]);
    limber::report::testing::write_reaction_run(argv[2], run);
    return 0;
  }
  CLI::App app{"limber report driver"};
  const limber::cli::Command report = limber::report::add_report_command(app);
  app.require_subcommand(1);
  CLI11_PARSE(app, argc, argv);
  try {
    return report.run();
  } catch (const limber::InputError& error) {
    std::fprintf(stderr, "limber: error: %s\n", error.what());
    return 1;
  }
}
