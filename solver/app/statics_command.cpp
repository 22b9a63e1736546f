// `limber statics`: the static equilibrium of a mechanism at t = 0 (docs/statics.md): flexible
// bodies deformed under the loads, every joint holding (hold-downs included). Prints the Newton
// iterations, residuals, free motions, stability and each joint's reaction; writes
// DIR/results.h5 with the equilibrium as its one sample, for render and report.
#include <fmt/format.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <memory>

#include "app/command.h"
#include "core/json_text.h"
#include "core/error.h"
#include "io/case_reader.h"
#include "io/case_reduction.h"
#include "io/mechanism_builder.h"
#include "multibody/reactions.h"
#include "results/results_writer.h"
#include "run/statics_run.h"

namespace limber::app {

namespace {

struct StaticsOptions {
  std::string case_file;
  std::string output_dir;
  bool json = false;
};

// Each joint's reaction on body j in its frame at the equilibrium (v̇ = 0).
multibody::Reactions equilibrium_reactions(const multibody::Model& model, const run::StaticsSummary& s) {
  multibody::Workspace ws(model);
  return multibody::compute_reactions(model, s.statics.state, Eigen::VectorXd::Zero(model.nv),
                                      s.start.partition, ws);
}

std::string json_vector(const Eigen::Vector3d& v) {
  return fmt::format("[{}, {}, {}]", json_number(v.x()), json_number(v.y()), json_number(v.z()));
}

std::string json_report(const multibody::Model& model, const run::StaticsSummary& s,
                        const multibody::Reactions* reactions, const std::string& results_path) {
  std::string joints = "[";
  for (std::size_t k = 0; reactions && k < model.joints.size(); ++k) {
    const multibody::JointReaction& r = reactions->joints[k];
    joints += fmt::format("{}{{\"name\": {}, \"force_joint\": {}, \"torque_joint\": {}, "
                          "\"force_ground\": {}, \"torque_ground\": {}, \"indeterminate\": {}}}",
                          k ? ", " : "", json_string(model.joints[k].name), json_vector(r.force_j_J),
                          json_vector(r.torque_j_J), json_vector(r.force_j_W), json_vector(r.torque_j_W),
                          r.indeterminate ? "true" : "false");
  }
  std::string free = "[";
  for (std::size_t k = 0; k < s.statics.free_motions.size(); ++k) {
    free += fmt::format("{}{{\"motion\": {}, \"load\": {}}}", k ? ", " : "",
                        json_string(s.statics.free_motions[k].description),
                        json_number(s.statics.free_motions[k].load));
  }
  return fmt::format(
      "{{\"status\": {}, \"message\": {}, \"iterations\": {}, \"force_residual\": {}, "
      "\"force_scale\": {}, \"constraint_residual\": {}, \"unstable_directions\": {}, "
      "\"free_motions\": {}], \"joints\": {}], \"wall_s\": {}, \"results\": {}}}",
      json_string(s.ok ? "ok" : "failed"), json_string(s.message), s.statics.iterations,
      json_number(s.statics.force_residual), json_number(s.statics.force_scale),
      json_number(s.statics.constraint_residual), s.statics.unstable_directions, free, joints,
      json_number(s.wall_seconds), json_string(results_path));
}

int solve_case_statics(const StaticsOptions& options) {
  const io::Case input = io::read_case_file(options.case_file);
  if (!input.mechanism) {
    throw InputError("expected a mechanism (a 'bodies' section), got none",
                     SourceLocation{options.case_file, 0, 0});
  }
  const io::CaseReduction reduction = io::reduce_case(input, io::ReductionScope::kMechanismBodies);
  const io::Mechanism mechanism = io::build_mechanism(input, reduction);
  const multibody::Model& model = mechanism.model;
  std::FILE* text = options.json ? stderr : stdout;
  fmt::print(text, "limber statics: {} ({})\n", input.title, input.file);

  const std::filesystem::path directory =
      options.output_dir.empty()
          ? std::filesystem::path("out") / (std::filesystem::path(options.case_file).stem().string() + "_statics")
          : std::filesystem::path(options.output_dir);
  results::ResultsWriter writer(directory, input.title, input.file);
  const std::string results_path = writer.path().string();
  const run::StaticsSummary summary = run::solve_mechanism_statics(model, mechanism.assembly, &writer);
  if (summary.failure == "assembly") {
    fmt::print(stderr, "limber: error: {}\n", summary.message);
    if (options.json) fmt::print(stdout, "{}\n", json_report(model, summary, nullptr, results_path));
    return kExitNumerical;
  }
  const multibody::StaticsResult& st = summary.statics;
  fmt::print(text, "statics: {} after {} Newton iterations: force residual {:.3g} of the largest force "
                   "{:.3g}, constraint residual {:.3g}, {:.3f} s wall\n",
             st.status == multibody::StaticsStatus::kOk ? "equilibrium" : "stopped", st.iterations,
             st.force_residual, st.force_scale, st.constraint_residual, summary.wall_seconds);
  // Free motions, alike ones counted together (a floating system has six of one kind).
  for (std::size_t k = 0; k < st.free_motions.size(); ++k) {
    const multibody::FreeMotion& free = st.free_motions[k];
    bool seen = false;
    int count = 0;
    double load = 0.0;
    for (std::size_t j = 0; j < st.free_motions.size(); ++j) {
      if (st.free_motions[j].description != free.description) continue;
      seen = seen || j < k;
      ++count;
      load = std::max(load, st.free_motions[j].load);
    }
    if (seen) continue;
    fmt::print(text, "free motion{} (no stiffness; load along it {:.3g}): {}\n",
               count > 1 ? fmt::format(" x{}", count) : "", load, free.description);
  }
  if (st.unstable_directions > 0) {
    fmt::print(stderr, "limber: warning: the equilibrium is unstable: {} direction(s) of negative "
                       "stiffness within the joints' freedom\n", st.unstable_directions);
  }
  const multibody::Reactions reactions = equilibrium_reactions(model, summary);
  fmt::print(text, "joint reactions on body j, joint frame (N, N m):\n");
  for (std::size_t k = 0; k < model.joints.size(); ++k) {
    const multibody::JointReaction& r = reactions.joints[k];
    fmt::print(text, "  {:<12} force [{:10.4g} {:10.4g} {:10.4g}]  torque [{:10.4g} {:10.4g} {:10.4g}]{}\n",
               model.joints[k].name, r.force_j_J.x(), r.force_j_J.y(), r.force_j_J.z(), r.torque_j_J.x(),
               r.torque_j_J.y(), r.torque_j_J.z(), r.indeterminate ? "  (indeterminate: minimum-norm)" : "");
  }
  fmt::print(text, "wrote {}\n", results_path);
  if (options.json) fmt::print(stdout, "{}\n", json_report(model, summary, &reactions, results_path));
  if (!summary.ok) {
    fmt::print(stderr, "limber: error: {}\n", summary.message);
    return kExitNumerical;
  }
  return kExitOk;
}

}  // namespace

Command add_statics_command(CLI::App& app) {
  auto options = std::make_shared<StaticsOptions>();
  CLI::App* cli = app.add_subcommand(
      "statics", "Static equilibrium: deformed shape, joint reactions; results.h5");
  cli->footer(
      "Solves Q(q) - G(q)^T lambda = 0, g(q) = 0 at rest by Newton's method with a line search\n"
      "(docs/statics.md): modal elastic forces, springs and their preloads, actuators, point loads\n"
      "and gravity against the joints, every joint holding (hold-downs with a 'release' time too).\n"
      "Motions with no stiffness (a floating spacecraft) are printed and left where they are; a\n"
      "load along one has no equilibrium and is an error naming the bodies and the direction.\n"
      "Writes DIR/results.h5 with the equilibrium as its one sample at t = 0 (render, report).\n"
      "Exit codes: 0 equilibrium found, 1 bad input, 2 no equilibrium (assembly failed, a load meets\n"
      "no stiffness, or Newton did not converge; the last iterate is written), 3 internal error.");
  cli->add_option("case", options->case_file, "Case file (YAML, docs/case-format.md)")->required();
  cli->add_option("-o,--output", options->output_dir,
                  "Output directory, created when missing (default: out/<case file stem>_statics)");
  cli->add_flag("--json", options->json,
                "Print exactly one JSON object on stdout: {\"status\" (\"ok\" or \"failed\"), \"message\", "
                "\"iterations\", \"force_residual\", \"force_scale\", \"constraint_residual\", "
                "\"unstable_directions\", \"free_motions\": [{\"motion\", \"load\"}], \"joints\": "
                "[{\"name\", \"force_joint\", \"torque_joint\", \"force_ground\", \"torque_ground\", "
                "\"indeterminate\"}], \"wall_s\", \"results\"}; the text goes to stderr");
  return {cli, [options] { return solve_case_statics(*options); }};
}

}  // namespace limber::app
