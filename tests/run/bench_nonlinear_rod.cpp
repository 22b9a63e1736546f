// limber_bench_nonlinear_rod: the nonlinear rod in a mechanism (issue 27), through the run driver
// (no file). (1) The seed set-up (cases/slider_crank_seed_setup_nonlinear.yaml) for `t_end`
// seconds: wall time, steps, Newton iterations and iteration matrices, and the peak mid-span
// deflection over the first 0.3 s, and the accuracy check's warnings. (2) The small-deformation
// limit on cases/slider_crank.yaml (0.05 m crank, spin-up ramp): the nonlinear rod, the modal rod
// (5 and 20 modes, inertia-only and full geometric stiffening), all undamped and without stress
// output (the case's text edited in memory), and the planar co-rotational rod of
// corotational_rod.h, compared in the peak deflection and the peak |R3| reaction. Not a test:
// prints figures for docs/nonlinear-beams.md.
//   limber_bench_nonlinear_rod [t_end of the seed run, default 1] [t_end of the comparison, default 0.5]
//                              [step of the seed run, default the case's]
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <ctime>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "io/case_reader.h"
#include "io/case_reduction.h"
#include "io/mechanism_builder.h"
#include "corotational_rod.h"
#include "modal/blas_threads.h"
#include "multibody/time_function.h"
#include "run/run_driver.h"

namespace {

using namespace limber;

struct Histories {
  run::RunSummary summary;
  std::vector<double> time, deflection, r3;  // rod deflection z [m], |R3 force| [N]
};

std::string read_text(const std::string& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  if (at == std::string::npos) {
    fmt::print(stderr, "not in the case: {}\n", from);
    std::exit(1);
  }
  return text.replace(at, from.size(), to);
}

Histories run_text(const std::string& text, double t_end, double step = 0.0) {
  const io::Case input = io::read_case_text(text, "bench.yaml");
  const io::Mechanism built = io::build_mechanism(input, io::reduce_case(input, io::ReductionScope::kMechanismBodies));
  io::RunSettings settings = built.run;
  settings.t_end = t_end;
  if (step > 0.0) settings.integrator.step = step;
  settings.sample_interval = 1e-3;
  const int r3 = built.model.find_joint("R3");
  Histories out;
  run::RunHooks hooks;
  hooks.on_sample = [&](const integrate::Sample& sample, const results::Sample& record) {
    out.time.push_back(sample.t);
    out.deflection.push_back(record.bodies[1].deflection.z());  // crank, rod, slider
    out.r3.push_back(record.joints[static_cast<std::size_t>(r3)].force_ground.norm());
  };
  out.summary = run::run_mechanism(built.model, built.assembly, settings, hooks);
  if (!out.summary.ok) fmt::print("  run failed: {}\n", out.summary.message);
  return out;
}

// CPU time of this process so far [s]: on a machine shared with other jobs, wall time measures
// the load as much as the program.
double cpu_seconds() { return static_cast<double>(std::clock()) / CLOCKS_PER_SEC; }

double peak(const std::vector<double>& x, const std::vector<double>& t, double until) {
  double m = 0.0;
  for (std::size_t k = 0; k < x.size(); ++k) {
    if (t[k] <= until + 1e-12) m = std::max(m, std::abs(x[k]));
  }
  return m;
}

}  // namespace

int main(int argc, char** argv) {
  // As limber's main: one BLAS thread (modal/blas_threads.h), so the figures compare.
  limber::modal::use_single_threaded_blas();
  const double seed_end = argc > 1 ? std::atof(argv[1]) : 1.0;
  const double limit_end = argc > 2 ? std::atof(argv[2]) : 0.5;
  const double seed_step = argc > 3 ? std::atof(argv[3]) : 0.0;
  const std::string cases = LIMBER_CASES_DIR;

  // (1) The seed set-up with the rod nonlinear.
  const Histories seed = run_text(read_text(cases + "/slider_crank_seed_setup_nonlinear.yaml"), seed_end, seed_step);
  const auto& s = seed.summary;
  fmt::print("seed set-up, nonlinear rod, {} s: {:.1f} s wall, {:.1f} s CPU, {} steps (h = {}), {} Newton "
             "iterations, {} iteration matrices, {} rejected steps, status {}, energy error {:.2e}, local error {:.2e}\n",
             seed_end, s.wall_seconds, cpu_seconds(), s.statistics.steps, seed_step > 0.0 ? fmt::format("{:g} s", seed_step) : std::string("the case's"), s.statistics.newton_iterations,
             s.statistics.jacobian_evaluations, s.statistics.rejected_steps, s.accurate() ? "ok" : "inaccurate",
             s.accuracy.energy_relative, s.accuracy.local_error);
  for (const std::string& warning : s.accuracy.warnings) fmt::print("  accuracy warning: {}\n", warning);
  fmt::print("  peak mid-span deflection over [0, 0.3] s: {:.3f} mm (unreduced co-rotational reference 38.5 mm)\n",
             1e3 * peak(seed.deflection, seed.time, 0.3));

  // (2) The small-deformation limit: modal rods (5 and 20 modes, with the default inertia-only
  // and with the full geometric stiffening) and the nonlinear rod, all undamped, no stress
  // output; and the independent planar co-rotational rod (corotational_rod.h) on the same
  // spin-up and gravity, its crank pin prescribed.
  if (limit_end <= 0.0) return 0;
  std::string modal = read_text(cases + "/slider_crank.yaml");
  modal = replaced(modal, "    damping: 0.01                   # ratio of critical, every mode\n", "    damping: 0\n");
  modal = replaced(modal, "    stress: {elements: all, every: 10}", "   ");
  const std::string nonlinear = replaced(modal, "    damping: 0\n", "    damping: 0\n    formulation: nonlinear\n");
  const std::string stiffened = replaced(modal, "    damping: 0\n", "    damping: 0\n    geometric_stiffening: true\n");
  const auto with_modes = [](const std::string& text, int modes) {
    return replaced(text, "      normal: 5\n", fmt::format("      normal: {}\n", modes));
  };
  const Histories n = run_text(nonlinear, limit_end);
  const double dn = peak(n.deflection, n.time, limit_end), rn = peak(n.r3, n.time, limit_end);
  fmt::print("slider_crank.yaml, 0 to {} s, undamped: nonlinear rod {:.1f} s wall, peak deflection {:.4f} mm, "
             "peak |R3| {:.3f} N, {} steps, {} Newton iterations\n",
             limit_end, n.summary.wall_seconds, 1e3 * dn, rn, n.summary.statistics.steps,
             n.summary.statistics.newton_iterations);
  for (const int modes : {5, 20}) {
    for (const bool full : {false, true}) {
      const Histories m = run_text(with_modes(full ? stiffened : modal, modes), limit_end);
      const double dm = peak(m.deflection, m.time, limit_end), rm = peak(m.r3, m.time, limit_end);
      double rms = 0.0, scale = 0.0;
      for (std::size_t k = 0; k < std::min(m.deflection.size(), n.deflection.size()); ++k) {
        rms += std::pow(m.deflection[k] - n.deflection[k], 2);
        scale += std::pow(n.deflection[k], 2);
      }
      fmt::print("  modal rod, {:2d} modes, stiffening {:12s}: peak deflection {:.4f} mm ({:+.2f} % from the nonlinear "
                 "rod), rms difference {:.2f} %, peak |R3| {:.3f} N ({:+.2f} %)\n",
                 modes, full ? "true" : "inertia_only", 1e3 * dm, 100.0 * (dn - dm) / dm, 100.0 * std::sqrt(rms / scale),
                 rm, 100.0 * (rn - rm) / rm);
    }
  }
  // The planar co-rotational rod: the seed set-up's rod on this case's crank, ramp and gravity.
  test::CorotationalRodSetup planar = test::seed_setup_rod(100, 2e-5);
  planar.crank = 0.05;
  planar.omega = 0.0;
  const multibody::TimeFunction ramp =
      multibody::TimeFunction::ramp(0.0, 125.66370614359172, 0.1, multibody::RampShape::kQuintic);
  planar.angle = [&ramp](double t) { return ramp.evaluate(t).value; };
  planar.gravity = 9.81;
  const std::vector<double> reference = test::corotational_midspan_deflection(planar, limit_end, 1e-3);
  double rms = 0.0, scale = 0.0, dp = 0.0;
  for (std::size_t k = 0; k < std::min(reference.size(), n.deflection.size()); ++k) {
    dp = std::max(dp, std::abs(reference[k]));
    rms += std::pow(std::abs(reference[k]) - std::abs(n.deflection[k]), 2);
    scale += std::pow(reference[k], 2);
  }
  fmt::print("  planar co-rotational rod (100 elements, HHT h = 2e-5 s): peak deflection {:.4f} mm ({:+.2f} % from the "
             "nonlinear rod), rms difference of |deflection| {:.2f} %\n",
             1e3 * dp, 100.0 * (dn - dp) / dp, 100.0 * std::sqrt(rms / scale));
  return 0;
}
