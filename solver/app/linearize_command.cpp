// `limber linearize`: the mechanism linearized about its assembled state at t = 0, its static
// equilibrium or the state a run reaches at T (run/linearize_run.h, run/linearize_at.h,
// docs/linearize.md). Prints the system's natural
// frequencies, damping ratios and rigid modes, the whole mechanism's mass properties and, with
// --reference-body, the modes with that body held and their effective masses; writes linear.h5,
// linear.mat (state space and tangent matrices) and the CSV files to DIR.
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
#include "multibody/hinge_limit.h"
#include "run/linear_file.h"
#include "run/linear_mat_file.h"
#include "run/linearize_at.h"
#include "run/linearize_run.h"
#include "run/system_mode_files.h"

namespace limber::app {

namespace {

struct LinearizeOptions {
  std::string case_file;
  std::string output_dir;
  std::string reference_body;
  double zero_hz = 0.0;
  int mode_files = 6;  // the first elastic system modes written as results files for render
  double at = 0.0;
  bool at_given = false;  // --at given (any value: linearize_at checks it against the run)
  bool statics = false;
  bool json = false;
};

std::string json_array(const Eigen::VectorXd& v) {
  std::string text = "[";
  for (Eigen::Index i = 0; i < v.size(); ++i) text += (i ? ", " : "") + json_number(v(i));
  return text + "]";
}

std::string json_matrix(const Eigen::MatrixXd& m) {
  std::string text = "[";
  for (Eigen::Index r = 0; r < m.rows(); ++r) text += (r ? ", " : "") + json_array(m.row(r).transpose());
  return text + "]";
}

std::string json_strings(const std::vector<std::string>& values) {
  std::string text = "[";
  for (std::size_t k = 0; k < values.size(); ++k) text += (k ? ", " : "") + json_string(values[k]);
  return text + "]";
}

std::string json_report(const run::LinearizeSummary& s, const std::vector<std::filesystem::path>& files) {
  std::string cantilevered = "null";
  if (s.cantilevered) {
    const multibody::CantileveredModes& c = *s.cantilevered;
    cantilevered = fmt::format(
        "{{\"reference_point\": {}, \"frequencies_hz\": {}, \"damping\": {}, \"rigid_modes\": {}, "
        "\"translational_coupling\": {}, \"rotational_coupling\": {}, \"effective_mass\": {}, "
        "\"effective_mass_sum\": {}, \"rigid_mass\": {}}}",
        json_array(c.p_WP), json_array(c.modes.frequencies_hz), json_array(c.modes.damping), c.modes.rigid_modes,
        json_matrix(c.participation.leftCols(3).transpose()), json_matrix(c.participation.rightCols(3).transpose()),
        json_matrix(c.effective_mass), json_array(c.effective_sum), json_matrix(c.rigid_mass));
  }
  const multibody::StateSpace& ss = s.state_space;
  const std::string state_space =
      fmt::format("{{\"states\": {}, \"inputs\": {}, \"outputs\": {}}}", ss.A.rows(), json_strings(ss.input_names),
                  json_strings(ss.output_names));
  std::vector<std::string> paths;
  for (const auto& file : files) paths.push_back(file.string());
  return fmt::format(
      "{{\"status\": {}, \"failure\": {}, \"message\": {}, \"about\": {}, \"t\": {}, \"free_motions\": {}, "
      "\"frequencies_hz\": {}, \"damping\": {}, \"undamped_hz\": {}, \"rigid_modes\": {}, \"unstable_modes\": {}, "
      "\"approximate_damping\": {}, \"zero_threshold_hz\": {}, \"largest_rigid_hz\": {}, \"mass\": {}, "
      "\"center_of_mass\": {}, \"inertia_about_com\": {}, "
      "\"state_space\": {}, \"cantilevered\": {}, \"files\": {}, \"wall_s\": {}}}",
      json_string(s.ok ? "ok" : "failed"), json_string(s.failure), json_string(s.message),
      json_string(run::linearization_point_kind(s)), json_number(s.point.t), s.free_motions, json_array(s.modes.frequencies_hz),
      json_array(s.modes.damping), json_array(s.modes.undamped_hz), s.modes.rigid_modes, s.modes.unstable_modes,
      s.modes.approximate_damping, json_number(s.modes.zero_threshold_hz), json_number(s.modes.largest_rigid_hz),
      json_number(s.mass.mass), json_array(s.mass.com_W),
      json_matrix(s.mass.inertia_com_W), state_space, cantilevered, json_strings(paths),
      json_number(s.wall_seconds));
}

// The first `count` entries of a mode list, "f Hz (ζ)" each.
void print_modes(std::FILE* text, const multibody::SystemModes& modes, int count) {
  int shown = 0;
  for (Eigen::Index i = 0; i < modes.frequencies_hz.size() && shown < count; ++i) {
    if (modes.frequencies_hz(i) == 0.0) continue;
    fmt::print(text, "  {:4d}  {:12.6g} Hz  damping ratio {:.4g}\n", i + 1, modes.frequencies_hz(i), modes.damping(i));
    ++shown;
  }
}

int linearize_case(const LinearizeOptions& options) {
  const io::Case input = io::read_case_file(options.case_file);
  if (!input.mechanism) {
    throw InputError("expected a mechanism (a 'bodies' section), got none", SourceLocation{options.case_file, 0, 0});
  }
  const io::CaseReduction reduction = io::reduce_case(input, io::ReductionScope::kMechanismBodies);
  const io::Mechanism mechanism = io::build_mechanism(input, reduction);
  const multibody::Model& model = mechanism.model;
  std::FILE* text = options.json ? stderr : stdout;
  fmt::print(text, "limber linearize: {} ({})\n", input.title, input.file);

  run::LinearizeSettings settings;
  settings.statics = options.statics;
  settings.reference_body = options.reference_body;
  settings.zero_threshold_hz = options.zero_hz;
  settings.inputs = io::linear_inputs(input.mechanism->linearize, model);
  settings.outputs = io::linear_outputs(input.mechanism->linearize, model);
  const run::LinearizeSummary s =
      options.at_given ? run::linearize_at(model, mechanism.assembly, input.mechanism->run, options.at, settings)
                        : run::linearize_mechanism(model, mechanism.assembly, settings);
  if (!s.ok) {
    fmt::print(stderr, "limber: error: {}\n", s.message);
    if (options.json) fmt::print(stdout, "{}\n", json_report(s, {}));
    return kExitNumerical;
  }
  const std::filesystem::path directory =
      options.output_dir.empty()
          ? std::filesystem::path("out") / (std::filesystem::path(options.case_file).stem().string() + "_linear")
          : std::filesystem::path(options.output_dir);
  std::vector<std::filesystem::path> files = run::write_linear_csv(model, s, directory);
  files.insert(files.begin(), run::write_linear_mat(model, s, directory));
  files.insert(files.begin(), run::write_linear_h5(model, s, directory, input.title, input.file));
  run::SystemModeFileOptions mode_files;
  mode_files.modes = options.mode_files;
  for (const auto& path : run::write_system_mode_files(model, s, directory, input.title, input.file, mode_files)) {
    files.push_back(path);
  }

  fmt::print(text, "about the {} at t = {:g} s: {} coordinates, {} free motions, {:.3f} s wall\n",
             s.at >= 0.0 ? (s.statics ? "static equilibrium from the state the run reaches" : "state the run reaches")
                         : s.statics ? "static equilibrium" : "assembled state",
             s.point.t, model.nv, s.free_motions, s.wall_seconds);
  if (s.at >= 0.0) {
    // Engaged (a latch locked, a stop in contact) or seated (a locked latch, its damping in full).
    const auto seated = std::count(s.point.engaged.begin(), s.point.engaged.end(), multibody::kLatchSeated);
    const auto engaged = std::count(s.point.engaged.begin(), s.point.engaged.end(), multibody::kLimitEngaged);
    fmt::print(text, "hinge latches and stops engaged at t = {:g} s: {} ({} of them latches seated)\n", s.point.t,
               engaged + seated, seated);
  }
  fmt::print(text, "rigid-body modes (zero frequency, below {:.3g} Hz): {} (the largest of them {:.3g} Hz before "
                   "zeroing)\n", s.modes.zero_threshold_hz, s.modes.rigid_modes, s.modes.largest_rigid_hz);
  // Zeros within a decade of the threshold are not clearly rigid (a state in motion).
  if (s.modes.rigid_modes > 0 && s.modes.largest_rigid_hz > 0.1 * s.modes.zero_threshold_hz) {
    fmt::print(stderr, "limber: warning: a rigid-body mode reached {:.3g} Hz, within a decade of the {:.3g} Hz "
                       "threshold: check the gap to the first elastic mode and set --zero-hz\n",
               s.modes.largest_rigid_hz, s.modes.zero_threshold_hz);
  }
  if (s.modes.unstable_modes > 0) {
    fmt::print(stderr, "limber: warning: {} unstable mode(s) (negative stiffness, reported as negative "
                       "frequencies)\n", s.modes.unstable_modes);
  }
  if (s.modes.approximate_damping > 0) {
    fmt::print(text, "{} mode(s) with their damping from the modal value (close, strongly damped modes)\n",
               s.modes.approximate_damping);
  }
  fmt::print(text, "first natural frequencies:\n");
  print_modes(text, s.modes, 10);
  const multibody::StateSpace& ss = s.state_space;
  fmt::print(text, "state space: {} states, {} inputs, {} outputs (the case's linearize section)\n", ss.A.rows(),
             ss.B.cols(), ss.C.rows());
  const multibody::MassProperties& m = s.mass;
  fmt::print(text, "mass {:.6g} kg, centre of mass [{:.5g} {:.5g} {:.5g}] m, inertia about it (ground axes, kg m^2):\n",
             m.mass, m.com_W.x(), m.com_W.y(), m.com_W.z());
  for (int r = 0; r < 3; ++r) {
    fmt::print(text, "  [{:12.6g} {:12.6g} {:12.6g}]\n", m.inertia_com_W(r, 0), m.inertia_com_W(r, 1),
               m.inertia_com_W(r, 2));
  }
  if (s.cantilevered) {
    const multibody::CantileveredModes& c = *s.cantilevered;
    fmt::print(text,
               "with {} held (about its centre of mass [{:.5g} {:.5g} {:.5g}] m): {} modes, {} of zero frequency\n",
               options.reference_body, c.p_WP.x(), c.p_WP.y(), c.p_WP.z(), c.modes.frequencies_hz.size(),
               c.modes.rigid_modes);
    print_modes(text, c.modes, 10);
    fmt::print(text, "effective masses summed over the held modes (T1-T3 kg, R1-R3 kg m^2): [{:.5g} {:.5g} {:.5g} "
                     "{:.5g} {:.5g} {:.5g}]\n", c.effective_sum(0), c.effective_sum(1), c.effective_sum(2),
               c.effective_sum(3), c.effective_sum(4), c.effective_sum(5));
    if (c.largest_constraint_rate > 1e-6) {
      fmt::print(stderr, "limber: warning: the mechanism cannot move as one rigid body (a joint to ground or a "
                         "driver): the rigid mass and effective masses are of a motion its joints forbid\n");
    }
  }
  for (const auto& path : files) fmt::print(text, "wrote {}\n", path.string());
  if (options.json) fmt::print(stdout, "{}\n", json_report(s, files));
  return kExitOk;
}

}  // namespace

Command add_linearize_command(CLI::App& app) {
  auto options = std::make_shared<LinearizeOptions>();
  CLI::App* cli = app.add_subcommand(
      "linearize",
      "Linearized mechanism: frequencies, damping, mass properties");
  cli->footer(
      "Tangent mass, damping and stiffness of the equations of motion by central differences,\n"
      "projected onto the motions the joints allow (null space of the constraint Jacobian, SVD),\n"
      "then the quadratic eigenproblem as a first-order problem (docs/linearize.md). Drivers are\n"
      "held; latches act in their current mode. Rigid-body modes are reported as zero frequencies.\n"
      "About the assembled start at t = 0 (default), the static equilibrium (--statics) or the\n"
      "state a run of the case reaches at T (--at T: hold-downs released, latches as switched;\n"
      "with --statics too, the static equilibrium reached from that state: a deployed spacecraft\n"
      "at rest, which a run still ringing at T is not).\n"
      "The state-space model A, B, C, D has the inputs and outputs of the case's `linearize`\n"
      "section (forces, torques at markers, RSDA actuator torques, driver efforts with the driver\n"
      "released; marker motions, joint reactions).\n"
      "Writes DIR/linear.h5 (tangent matrices, null-space basis, modes, state space, mass\n"
      "properties, held modes), DIR/linear.mat (MATLAB v5: A, B, C, D, M, C_damping, K, ...),\n"
      "DIR/linear_modes.csv, DIR/mode_shapes.csv, DIR/mass_properties.csv,\n"
      "DIR/state_space_{A,B,C,D}.csv, DIR/system_modes/mode_<kk>/results.h5 (one period of each of\n"
      "the first elastic modes, for `limber render`) and, with\n"
      "--reference-body, DIR/cantilevered_modes.csv (modes with that body held, participation\n"
      "factors and effective masses T1-T3, R1-R3).\n"
      "Exit codes: 0 done, 1 bad input, 2 numerical failure (assembly, statics, the run to T, singular\n"
      "constraints).");
  cli->add_option("case", options->case_file, "Case file (YAML, docs/case-format.md)")->required();
  cli->add_option("-o,--output", options->output_dir,
                  "Output directory, created when missing (default: out/<case file stem>_linear)");
  cli->add_flag("--statics", options->statics, "Linearize about the static equilibrium at t = 0 (docs/statics.md), or with --at the one "
                "reached from the run's state at T");
  CLI::Option* at = cli->add_option("--at", options->at,
                  "Linearize about the state a run of the case reaches at this time [s] (0 < T <= run.t_end; "
                  "the case's run settings, no results.h5)");
  cli->add_option("--reference-body", options->reference_body,
                  "Body held for the cantilevered modes and effective masses (e.g. the satellite's bus)");
  cli->add_option("--mode-files", options->mode_files,
                  "Elastic system modes written as DIR/system_modes/mode_<kk>/results.h5, one period each, "
                  "for `limber render` (default 6; 0: none)")
      ->check(CLI::Range(0, 1000));
  cli->add_option("--zero-hz", options->zero_hz,
                  "Frequencies at or below this are rigid-body modes [Hz] (default: 1e-4 of the highest)")
      ->check(CLI::Range(0.0, 1e9));
  cli->add_flag("--json", options->json,
                "Print exactly one JSON object on stdout: {\"status\", \"failure\", \"message\", \"about\" "
                "(\"assembly\", \"statics\" or \"run\"), \"t\", "
                "\"free_motions\", \"frequencies_hz\", \"damping\", \"undamped_hz\", \"rigid_modes\", "
                "\"unstable_modes\", \"approximate_damping\", \"zero_threshold_hz\", \"largest_rigid_hz\", \"mass\", "
                "\"center_of_mass\", \"inertia_about_com\", \"state_space\" ({\"states\", \"inputs\", \"outputs\"}: the "
                "number of states and the input and output names), "
                "\"cantilevered\" (null or {\"reference_point\", \"frequencies_hz\", \"damping\", \"rigid_modes\", "
                "\"translational_coupling\", \"rotational_coupling\", \"effective_mass\", \"effective_mass_sum\", "
                "\"rigid_mass\"}), \"files\", \"wall_s\"}; the text goes to stderr");
  return {cli, [options, at] {
            options->at_given = at->count() > 0;
            return linearize_case(*options);
          }};
}

}  // namespace limber::app
