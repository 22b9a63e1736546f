// Chains of N parallelograms sharing their cranks (tests/run/data/parallelogram_chain_N.yaml,
// issue 31) run through the run driver, measured against their closed form: on the
// parallelogram branch every crank turns at the driven angle θ = ω t and every coupler
// translates, coupler k's origin at (0.3 k + a sin θ, 0, a cos θ). Shared by the tests and the
// settings table (bench_singular_family.cpp).
#pragma once

#include <cmath>
#include <string>

#include "singular_family.h"

namespace limber::test {

inline std::string parallelogram_chain_stem(int n) { return "parallelogram_chain_" + std::to_string(n); }

struct ChainRun {
  run::RunSummary summary;
  double max_error = 0.0;  // over the samples: largest coupler origin error [m]
  double end_error = 0.0;  // the same at the last sample [m]
};

// Runs the N-chain to t_end at the setting (singular_family.h).
inline ChainRun run_parallelogram_chain(int n, integrate::Method method, double rtol_or_step, double t_end) {
  constexpr double kCrank = 0.1, kSpacing = 0.3, kOmega = 4.0 * M_PI;  // m, m, rad/s (2 rev/s)
  const io::Mechanism built = build_test_case(parallelogram_chain_stem(n));
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
  out.summary = run_at_setting(built, method, rtol_or_step, t_end, hooks);
  return out;
}

}  // namespace limber::test
