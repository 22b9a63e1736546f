#include "mechanism_run_path.h"

#include <fmt/format.h>

#include <chrono>
#include <cmath>

#include "core/error.h"
#include "io/case_reader.h"
#include "io/case_reduction.h"
#include "io/mechanism_builder.h"
#include "results/results_writer.h"
#include "results/results_layout.h"
#include "run/run_driver.h"

namespace limber::fuzz {
namespace {

bool finite(const Eigen::VectorXd& values) { return values.allFinite(); }

// The first rule a finished run broke, or "".
std::string check_summary(const run::RunSummary& summary) {
  if (!summary.ok) {
    if (summary.failure.empty() || summary.message.empty()) {
      return fmt::format("a failure without a name or message (failure '{}', message '{}')",
                         summary.failure, summary.message);
    }
    return "";
  }
  if (summary.t_reached != summary.t_end) {
    return fmt::format("status ok at t = {:g} s, before t_end = {:g} s", summary.t_reached, summary.t_end);
  }
  if (!std::isfinite(summary.max_position_violation) || !std::isfinite(summary.max_velocity_violation)) {
    return "non-finite constraint violation in the summary";
  }
  return "";
}

}  // namespace

MechanismOutcome run_mechanism_case(const std::string& text, const std::string& file,
                                    integrate::Method method, const std::string& output_dir) {
  MechanismOutcome outcome;
  const auto start = std::chrono::steady_clock::now();
  try {
    const io::Case input = io::read_case_text(text, file);
    if (!input.mechanism) throw InputError("expected a mechanism, got none", SourceLocation{file, 0, 0});
    io::RunSettings settings = input.mechanism->run;
    settings.integrator.method = method;
    run::check_settings(settings);
    const io::CaseReduction reduction = io::reduce_case(input, io::ReductionScope::kMechanismBodies);
    const io::Mechanism mechanism = io::build_mechanism(input, reduction);

    results::ResultsWriter writer(output_dir, input.title, file);
    run::RunHooks hooks;
    hooks.writer = &writer;
    // Every sample's state must be finite (the integrators stop on NaN before a sample).
    hooks.on_sample = [&](const integrate::Sample& sample, const results::Sample&) {
      if (outcome.finding.empty() &&
          !(finite(sample.q) && finite(sample.v) && finite(sample.vdot) && finite(sample.lambda))) {
        outcome.finding = fmt::format("a non-finite value in the sample at t = {:g} s", sample.t);
      }
    };
    const run::RunSummary summary =
        run::run_mechanism(mechanism.model, mechanism.assembly, settings, hooks);
    outcome.samples = summary.samples;
    outcome.message = summary.message;
    if (outcome.finding.empty()) outcome.finding = check_summary(summary);
    namespace status = results::layout::status;
    outcome.status = !summary.ok          ? std::string(status::kFailed) + ": " + summary.failure
                     : summary.accurate() ? status::kOk
                                          : status::kInaccurate;
  } catch (const InputError& e) {
    outcome.status = "InputError";
    outcome.message = e.what();
  } catch (const NumericalError& e) {
    outcome.status = "NumericalError";
    outcome.message = e.what();
  }
  outcome.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return outcome;
}

}  // namespace limber::fuzz
