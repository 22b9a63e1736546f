// Chains of N parallelograms sharing their cranks (tests/run/data/parallelogram_chain_N.yaml,
// issue 31) run through the run driver, measured against their closed form: on the
// parallelogram branch every crank turns at the driven angle θ = ω t and every coupler
// translates, coupler k's origin at (0.3 k + a sin θ, 0, a cos θ). Shared by the tests and the
// settings table (bench_parallelogram_chain.cpp).
#pragma once

#include <algorithm>
#include <cmath>
#include <string>

#include "io/case_reader.h"
#include "io/case_reduction.h"
#include "io/mechanism_builder.h"
#include "run/run_driver.h"
#include "run_test_support.h"

namespace limber::test {

inline std::string parallelogram_chain_path(int n) {
  return std::string(LIMBER_TEST_DATA_DIR) + "/parallelogram_chain_" + std::to_string(n) + ".yaml";
}

struct ChainRun {
  run::RunSummary summary;
  double max_error = 0.0;  // over the samples: largest coupler origin error [m]
  double end_error = 0.0;  // the same at the last sample [m]
};

// Runs the N-chain to t_end with IDA at rtol (atol rtol/100, at least 1e-10: at rtol 1e-10 and
// atol 1e-12 IDA fails at t = 8e-6 s, no singularity near) or generalized-α at step.
inline ChainRun run_parallelogram_chain(int n, integrate::Method method, double rtol_or_step, double t_end) {
  constexpr double kCrank = 0.1, kSpacing = 0.3, kOmega = 4.0 * M_PI;  // m, m, rad/s (2 rev/s)
  const std::string path = parallelogram_chain_path(n);
  const io::Case input = io::read_case_text(read_text(path), path);
  const io::Mechanism built =
      io::build_mechanism(input, io::reduce_case(input, io::ReductionScope::kMechanismBodies));
  io::RunSettings settings = built.run;
  settings.t_end = t_end;
  settings.integrator.method = method;
  if (method == integrate::Method::kIda) {
    settings.integrator.rtol = rtol_or_step;
    settings.integrator.atol = std::max(1e-2 * rtol_or_step, 1e-10);  // tighter fails at the start (docs/integrators.md)
  } else {
    settings.integrator.step = rtol_or_step;
  }
  std::vector<int> couplers;
  for (int k = 0; k < n; ++k) {
    couplers.push_back(built.model.bodies[built.model.find_body("coupler" + std::to_string(k))].q_offset);
  }
  ChainRun out;
  run::RunHooks hooks;
  hooks.on_sample = [&](const integrate::Sample& sample, const results::Sample&) {
    const double theta = kOmega * sample.t;
    double error = 0.0;
    for (int k = 0; k < n; ++k) {
      const Eigen::Vector3d expected(kSpacing * k + kCrank * std::sin(theta), 0.0, kCrank * std::cos(theta));
      error = std::max(error, (sample.q.segment<3>(couplers[static_cast<std::size_t>(k)]) - expected).norm());
    }
    out.max_error = std::max(out.max_error, error);
    out.end_error = error;
  };
  out.summary = run::run_mechanism(built.model, built.assembly, settings, hooks);
  return out;
}

}  // namespace limber::test
