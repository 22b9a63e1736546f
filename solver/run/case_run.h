// A case file's run as `limber run` does it, shared with the Python module (solver/python) so
// that both write the same results.h5: the case's run settings with the caller's overrides,
// checked; its flexible bodies reduced and its mechanism built (io: read -> reduce -> build);
// DIR/results.h5 (or the same file in memory) opened with the case's names; then run_mechanism
// (run_driver.h), the file closed as "interrupted" or "failed" when a hook stops the run or
// something throws.
#pragma once

#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include "io/case_reader.h"
#include "io/case_reduction.h"
#include "io/mechanism_builder.h"
#include "results/results_writer.h"
#include "run/run_driver.h"
#include "run/settings_overrides.h"

namespace limber::run {

// A case ready to run.
struct CaseRun {
  io::RunSettings settings;  // the case's, with the overrides applied
  io::CaseReduction reduction;
  io::Mechanism mechanism;
};

// Throws InputError when `input` has no mechanism, when the overrides or the settings cannot
// run (check_settings) or when the build finds bad input (at file:line:col); NumericalError
// when a flexible body's reduction failed. `modes`: normal_mode_overrides.
CaseRun prepare_case_run(const io::Case& input, const SettingsOverrides& overrides,
                         std::optional<int> modes = std::nullopt);

// DIR/results.h5 for `input` (its title, case file and axis names); DIR is created when missing.
std::unique_ptr<results::ResultsWriter> open_case_results(const std::filesystem::path& directory,
                                                          const io::Case& input);
// The same file kept in memory (results::InMemoryFile): its bytes in file_image() once the run
// has finished it; nothing is written to disk.
std::unique_ptr<results::ResultsWriter> open_case_results_in_memory(const io::Case& input);

// Thrown by a hook to stop the run between samples (a signal, a Python KeyboardInterrupt).
struct RunStopped {
  std::string message;  // "interrupted by ... after t = ... s", the file's message
};

// Runs `run` into `writer` (hooks.writer is set to it), which the run finishes. When a hook
// throws RunStopped the file is closed as "interrupted" with its message, and any other
// exception closes it as "failed" with its what(); both are rethrown.
RunSummary run_case(const CaseRun& run, results::ResultsWriter& writer, RunHooks hooks);

}  // namespace limber::run
