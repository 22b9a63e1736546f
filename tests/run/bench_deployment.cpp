// limber_bench_deployment: error against cost of both integrators on the satellite solar-array
// deployment (cases/satellite_deployment.yaml), 0 to 4.7 s (both latch-ups and 0.5 s of
// ringing after the last), samples every 0.25 ms, through the run driver (no file).
// Compared with a reference run (generalized-α, h = 25 µs): the latch times, and the latch-up
// peaks of the root hinge R3 (the bus reaction) and the panel hinge R1 — the largest |force|
// in ground axes within 0.5 s after each joint's latch event, and the largest latch torque.
// Wall time: one run each (they take seconds to a minute). Then the seed's Figs. 9-10 question
// on this scene: the same run (gen-α, h = 0.25 ms) with other panel mode sets, the case's text
// edited in memory. Not a test: prints tables for docs/benchmarks.md.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <variant>
#include <vector>

#include "io/case_reader.h"
#include "io/case_reduction.h"
#include "io/mechanism_builder.h"
#include "modal/blas_threads.h"
#include "run/run_driver.h"

namespace {

using namespace limber;

constexpr double kWindow = 0.5;  // s after a latch event searched for its peak

// What a run says about one latched joint.
struct LatchUp {
  double time = NAN;         // latch event [s]
  double peak_force = 0.0;   // max |reaction| in the window [N]
  double peak_torque = 0.0;  // max |latch torque| in the window [N m]
};

struct Outcome {
  run::RunSummary summary;
  LatchUp root, panel;  // R3 (bus - panel_R1) and R1 (panel_R1 - panel_R2)
};

// The panel's mode request in cases/satellite_deployment.yaml, and the alternatives compared.
constexpr const char* kNormalModes = "      normal: 8\n";
struct ModeSet {
  const char* label;
  const char* request;  // replaces kNormalModes
};
constexpr ModeSet kModeSets[] = {
    {"8 normal (the case)", kNormalModes},
    {"8 normal + attachment uy, uz at both hinge nodes",
     "      normal: 8\n      attachment: [{nodes: [root_edge, outer_edge], dofs: [uy, uz]}]\n"},
    {"20 normal", "      normal: 20\n"},
};

Outcome run_once(const io::Mechanism& mechanism, const integrate::IntegratorOptions& options) {
  const multibody::Model& model = mechanism.model;
  io::RunSettings settings = mechanism.run;
  settings.integrator = options;
  settings.t_end = 4.7;
  settings.sample_interval = 2.5e-4;
  const int root_joint = model.find_joint("R3"), panel_joint = model.find_joint("R1");
  // Latch torques are recorded per hinge limit, in model order.
  int root_limit = -1, panel_limit = -1, limits = 0;
  for (const multibody::ForceElement& force : model.forces) {
    if (!std::holds_alternative<multibody::HingeLimit>(force)) continue;
    const auto& limit = std::get<multibody::HingeLimit>(force);
    if (limit.joint == root_joint) root_limit = limits;
    if (limit.joint == panel_joint) panel_limit = limits;
    ++limits;
  }
  Outcome outcome;
  run::RunHooks hooks;
  hooks.on_event = [&](const multibody::HingeEvent& event) {
    const auto& limit = std::get<multibody::HingeLimit>(model.forces[event.force]);
    if (limit.joint == root_joint) outcome.root.time = event.t;
    if (limit.joint == panel_joint) outcome.panel.time = event.t;
  };
  const auto track = [](LatchUp& latch, double t, const results::Sample& record, int joint, int limit) {
    if (!(t >= latch.time && t <= latch.time + kWindow)) return;
    latch.peak_force = std::max(latch.peak_force, record.joints[joint].force_ground.norm());
    latch.peak_torque = std::max(latch.peak_torque, std::abs(record.hinge_limit_torques[limit]));
  };
  hooks.on_sample = [&](const integrate::Sample& sample, const results::Sample& record) {
    track(outcome.root, sample.t, record, root_joint, root_limit);
    track(outcome.panel, sample.t, record, panel_joint, panel_limit);
  };
  outcome.summary = run::run_mechanism(model, mechanism.assembly, settings, hooks);
  return outcome;
}

double relative(double value, double reference) { return std::abs(value - reference) / std::abs(reference); }

void print_row(const char* method, const std::string& setting, const Outcome& o, const Outcome& ref) {
  const integrate::Statistics& s = o.summary.statistics;
  if (!o.summary.ok) {
    fmt::print("| {} | {} | failed: {} | | | | | |\n", method, setting, o.summary.message);
    return;
  }
  fmt::print("| {} | {} | {:.1f} | {} | {:.1e} | {:.2f} % | {:.2f} % | {:.2f} % |\n", method, setting,
             o.summary.wall_seconds, s.steps,
             std::max(std::abs(o.root.time - ref.root.time), std::abs(o.panel.time - ref.panel.time)),
             100 * relative(o.root.peak_force, ref.root.peak_force),
             100 * relative(o.panel.peak_force, ref.panel.peak_force),
             100 * std::max(relative(o.root.peak_torque, ref.root.peak_torque),
                            relative(o.panel.peak_torque, ref.panel.peak_torque)));
  std::fflush(stdout);
}

}  // namespace

std::string read_text(const std::string& path) {
  std::ifstream file(path);
  std::stringstream text;
  text << file.rdbuf();
  return text.str();
}

void compare_mode_sets(const std::string& path) {
  const std::string text = read_text(path);
  const std::size_t at = text.find(kNormalModes);
  if (at == std::string::npos) {
    fmt::print("mode-set comparison skipped: '{}' no longer requests 8 normal modes\n", path);
    return;
  }
  fmt::print("\n| panel modes | modes per panel | wall [s] | R3 latch [s] | R3 peak force [N] | R1 latch [s] "
             "| R1 peak force [N] | R1 latch torque [N m] |\n|---|---|---|---|---|---|---|---|\n");
  for (const ModeSet& set : kModeSets) {
    std::string edited = text;
    edited.replace(at, std::string(kNormalModes).size(), set.request);
    const io::Case input = io::read_case_text(edited, path);
    const io::Mechanism built = io::build_mechanism(input, io::reduce_case(input, io::ReductionScope::kMechanismBodies));
    const Outcome o = run_once(built, integrate::IntegratorOptions::generalized_alpha(2.5e-4, 0.8));
    const int panel = built.model.find_body("panel_R2");
    fmt::print("| {} | {} | {:.1f} | {:.5f} | {:.2f} | {:.5f} | {:.2f} | {:.2f} |\n", set.label,
               built.model.bodies[panel].flexible->mode_count(), o.summary.wall_seconds,
               o.root.time, o.root.peak_force, o.panel.time, o.panel.peak_force, o.panel.peak_torque);
    std::fflush(stdout);
  }
}

int main() {
  // As limber's main: one BLAS thread (modal/blas_threads.h), so the figures compare.
  limber::modal::use_single_threaded_blas();
  const std::string path = std::string(LIMBER_CASES_DIR) + "/satellite_deployment.yaml";
  const io::Case input = io::read_case_file(path);
  const io::Mechanism mechanism = io::build_mechanism(input, io::reduce_case(input, io::ReductionScope::kMechanismBodies));
  const Outcome ref = run_once(mechanism, integrate::IntegratorOptions::generalized_alpha(2.5e-5, 0.8));
  if (!ref.summary.ok) {
    fmt::print("reference run failed: {}\n", ref.summary.message);
    return 2;
  }
  fmt::print("reference gen-alpha h = 25 us ({:.0f} s): R3 latches at {:.6f} s, peak |F| {:.2f} N, "
             "latch torque {:.2f} N m; R1 latches at {:.6f} s, peak |F| {:.2f} N, latch torque "
             "{:.2f} N m\n\n",
             ref.summary.wall_seconds, ref.root.time, ref.root.peak_force, ref.root.peak_torque,
             ref.panel.time, ref.panel.peak_force, ref.panel.peak_torque);
  fmt::print("| integrator | setting | wall [s] | steps | latch time error [s] | R3 peak force error "
             "| R1 peak force error | latch torque error (max) |\n|---|---|---|---|---|---|---|---|\n");
  for (double h : {1e-3, 5e-4, 2.5e-4, 1e-4}) {
    print_row("gen-α", fmt::format("h {:.1e}, ρ∞ 0.8", h),
              run_once(mechanism, integrate::IntegratorOptions::generalized_alpha(h, 0.8)), ref);
  }
  for (double rtol : {1e-4, 1e-6}) {
    print_row("IDA (BDF ≤ 2)", fmt::format("rtol {:.0e}, atol {:.0e}", rtol, rtol / 100),
              run_once(mechanism, integrate::IntegratorOptions::ida(rtol, rtol / 100)), ref);
  }
  compare_mode_sets(path);
  return 0;
}
