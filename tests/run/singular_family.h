// The family of mechanisms issue 31 runs through their singular or overconstrained positions
// (parallelogram chains, Bricard's linkage, a five-bar; tests/run/data) at one integrator setting
// each: the case read, reduced and built as `limber run` does, the setting applied the same way
// for the tests and for the settings table (bench_singular_family.cpp).
#pragma once

#include <algorithm>
#include <filesystem>
#include <string>

#include "io/case_reader.h"
#include "io/case_reduction.h"
#include "io/mechanism_builder.h"
#include "results/results_writer.h"
#include "run/run_driver.h"
#include "run_test_support.h"

namespace limber::test {

inline std::string test_case_path(const std::string& stem) {
  return std::string(LIMBER_TEST_DATA_DIR) + "/" + stem + ".yaml";
}

inline io::Mechanism build_case_text(const std::string& text, const std::string& path) {
  const io::Case input = io::read_case_text(text, path);
  return io::build_mechanism(input, io::reduce_case(input, io::ReductionScope::kMechanismBodies));
}

inline io::Mechanism build_test_case(const std::string& stem) {
  const std::string path = test_case_path(stem);
  return build_case_text(read_text(path), path);
}

// The case's run settings to t_end with IDA at rtol (atol rtol/100, at least 1e-10, the rule
// the parallelogram chains' table was measured with: docs/integrators.md; `atol` instead when
// positive) or generalized-α at `step`.
inline io::RunSettings settings_at(const io::Mechanism& built, integrate::Method method,
                                   double rtol_or_step, double t_end, double atol = 0.0) {
  io::RunSettings settings = built.run;
  settings.t_end = t_end;
  settings.integrator.method = method;
  if (method == integrate::Method::kIda) {
    settings.integrator.rtol = rtol_or_step;
    settings.integrator.atol = atol > 0.0 ? atol : std::max(1e-2 * rtol_or_step, 1e-10);
  } else {
    settings.integrator.step = rtol_or_step;
  }
  return settings;
}

// Runs `built` at the setting with `hooks`; with `results_dir` non-empty, results.h5 is written
// there too.
inline run::RunSummary run_at_setting(const io::Mechanism& built, integrate::Method method, double rtol_or_step,
                                      double t_end, run::RunHooks hooks,
                                      const std::filesystem::path& results_dir = {}, double atol = 0.0) {
  const io::RunSettings settings = settings_at(built, method, rtol_or_step, t_end, atol);
  if (results_dir.empty()) return run::run_mechanism(built.model, built.assembly, settings, hooks);
  results::ResultsWriter writer(results_dir, "singular family", "");
  hooks.writer = &writer;
  return run::run_mechanism(built.model, built.assembly, settings, hooks);
}

}  // namespace limber::test
