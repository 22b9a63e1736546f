#include "run/case_run.h"

#include "core/error.h"
#include "io/formulation_override.h"

namespace limber::run {

CaseRun prepare_case_run(const io::Case& input, const SettingsOverrides& overrides,
                         std::optional<int> modes) {
  if (!input.mechanism) {
    throw InputError("expected a mechanism (a 'bodies' section), got none", SourceLocation{input.file, 0, 0});
  }
  CaseRun run;
  run.settings = overrides.apply(input.mechanism->run);
  check_settings(run.settings);
  if (io::nonlinear_formulation_requested(overrides.formulation, "--formulation")) {
    io::Case nonlinear = input;
    io::make_flexible_bodies_nonlinear(nonlinear);
    run.reduction = io::reduce_case(nonlinear, io::ReductionScope::kMechanismBodies);
    run.mechanism = io::build_mechanism(nonlinear, run.reduction);
    return run;
  }
  run.reduction = io::reduce_case(input, io::ReductionScope::kMechanismBodies, normal_mode_overrides(input, modes));
  run.mechanism = io::build_mechanism(input, run.reduction);
  return run;
}

namespace {

// The case's names for the ground axes, when it gives them.
std::unique_ptr<results::ResultsWriter> with_axis_names(std::unique_ptr<results::ResultsWriter> writer,
                                                        const io::Case& input) {
  if (input.axis_names.size() == 3) {
    writer->set_axis_names({input.axis_names[0], input.axis_names[1], input.axis_names[2]});
  }
  return writer;
}

}  // namespace

std::unique_ptr<results::ResultsWriter> open_case_results(const std::filesystem::path& directory,
                                                          const io::Case& input) {
  return with_axis_names(std::make_unique<results::ResultsWriter>(directory, input.title, input.file), input);
}

std::unique_ptr<results::ResultsWriter> open_case_results_in_memory(const io::Case& input) {
  return with_axis_names(
      std::make_unique<results::ResultsWriter>(results::InMemoryFile{}, input.title, input.file), input);
}

RunSummary run_case(const CaseRun& run, results::ResultsWriter& writer, RunHooks hooks) {
  hooks.writer = &writer;
  try {
    return run_mechanism(run.mechanism.model, run.mechanism.assembly, run.settings, hooks);
  } catch (const RunStopped& stop) {
    writer.finish(results::RunStatus::kInterrupted, stop.message);
    throw;
  } catch (const std::exception& error) {
    writer.finish(results::RunStatus::kFailed, error.what());
    throw;
  }
}

}  // namespace limber::run
