#include "report_command.h"

#include "report_job.h"

#include <fmt/core.h>

#include <memory>

namespace limber::report {

cli::Command add_report_command(CLI::App& app) {
  // Options live as long as the app (run() is called after parsing).
  auto options = std::make_shared<ReportOptions>();
  auto no_modes = std::make_shared<bool>(false);

  CLI::App* command = app.add_subcommand(
      "report", "Write an HTML report of one or more run directories: a summary\n"
                "(status, events, peak reactions), then plots of reactions, energy,\n"
                "deflection, violation (docs/report.md)");
  command->add_option("DIR", options->directories,
                      "run directories holding results.h5; several: plots compare them")
      ->required();
  command->add_option("-o,--output", options->output, "report folder (default: DIR/report)");
  command->add_option("--title", options->title, "page title (default: the case title)");
  command->add_flag("--no-mode-shapes", *no_modes, "do not draw the mode shapes");
  command->add_option("--frame", options->frames,
                      "frame of the reaction plots, repeatable, in order: ground (default; the "
                      "case's axis names), joint (the joint frame: marker j's axes), a marker "
                      "(e.g. R1.j: the case names a joint's markers <joint>.i and <joint>.j) or a "
                      "body (e.g. crank): components rotated into that frame at every sample")
      // One value per --frame: `--frame joint DIR` leaves DIR to the positional argument.
      ->allow_extra_args(false);
  command->add_option("--config", options->config,
                      "report config (YAML) listing plots, each with a kind: reaction (joint, "
                      "frame, quantity force|torque, components x, y, z, magnitude), probe (body, "
                      "components), modal (body, modes), drivers (drivers), deflection, energy, "
                      "energy_balance, energy_residual, violation, hinge_angles, latch_torques, "
                      "clearance, peak_stress; each with title, window [from, to] s and y_axis "
                      "log|linear; they replace the default plots of the kinds listed "
                      "(docs/report.md; example: cases/slider_crank_report.yaml)");
  command->add_option("--zero-fraction", options->zero_fraction,
                      "a reaction component whose peak is below this fraction of the joint's "
                      "largest is listed as '≈ 0 (peak …)' instead of drawn (default 1e-4)")
      ->check(CLI::Range(0.0, 1.0));


  return {command, [options, no_modes] {
            options->mode_shapes = !*no_modes;
            const ReportSummary summary = generate_report(*options);
            for (const std::string& run : summary.runs_not_ok) {
              fmt::print(stderr, "limber report: warning: run did not finish ok ({})\n", run);
            }
            fmt::print("{} plots, {} mode-shape images\n{}\n", summary.plots, summary.mode_images,
                       summary.index.string());
            return cli::kExitOk;
          }};
}

}  // namespace limber::report
