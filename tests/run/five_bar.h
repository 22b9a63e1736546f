// The planar five-bar driven through its stretched, singular configuration
// (tests/run/data/five_bar_singular.yaml, issue 31), measured against its closed form: with the
// cranks at theta = omega t and pi - theta, P = (0, 0, a sin theta + cos(theta/2) K(theta)),
// K = sqrt(2 a (2 c + a (1 - cos theta))), the branch that keeps the velocity continuous through
// theta = pi + 2 pi k. Shared by the tests and the settings table (bench_singular_family.cpp).
#pragma once

#include <algorithm>
#include <cmath>
#include <string>

#include "singular_family.h"

namespace limber::test {

inline constexpr const char* kFiveBarStem = "five_bar_singular";

// P on the branch through the singular configurations at crank angle theta [m].
inline Eigen::Vector3d five_bar_p(double theta) {
  constexpr double a = 0.1, c = 0.15;  // crank, half the ground [m]
  const double k = std::sqrt(2.0 * a * (2.0 * c + a * (1.0 - std::cos(theta))));
  return {0.0, 0.0, a * std::sin(theta) + std::cos(0.5 * theta) * k};
}

struct FiveBarRun {
  run::RunSummary summary;
  double max_error = 0.0;  // over the samples: largest |P - closed form| [m]
  double end_error = 0.0;  // the same at the last sample [m]
};

// Runs the five-bar to t_end at the setting (singular_family.h), results.h5 into `results_dir`
// when given.
inline FiveBarRun run_five_bar(integrate::Method method, double rtol_or_step, double t_end,
                               const std::filesystem::path& results_dir = {}) {
  constexpr double kOmega = 2.0 * M_PI;  // both cranks [rad/s]
  const io::Mechanism built = build_test_case(kFiveBarStem);
  // distal1's origin is P.
  const int p = built.model.bodies[static_cast<std::size_t>(built.model.find_body("distal1"))].q_offset;
  FiveBarRun out;
  run::RunHooks hooks;
  hooks.on_sample = [&](const integrate::Sample& sample, const results::Sample&) {
    const double error = (sample.q.segment<3>(p) - five_bar_p(kOmega * sample.t)).norm();
    out.max_error = std::max(out.max_error, error);
    out.end_error = error;
  };
  out.summary = run_at_setting(built, method, rtol_or_step, t_end, hooks, results_dir);
  return out;
}

}  // namespace limber::test
