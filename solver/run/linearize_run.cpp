#include "run/linearize_run.h"

#include <chrono>
#include <fstream>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "core/error.h"

namespace limber::run {

namespace {

// The body's index, or InputError naming the bodies there are.
int reference_body_index(const multibody::Model& model, const std::string& name) {
  const int index = model.find_body(name);
  if (index > 0 && model.bodies[static_cast<std::size_t>(index)].nv > 0) return index;
  std::vector<std::string> names;
  for (const multibody::Body& body : model.bodies) {
    if (body.nv > 0) names.push_back(body.name);
  }
  throw InputError(fmt::format("--reference-body: expected a moving body of the case ({}), got '{}'",
                               fmt::join(names, ", "), name));
}

// A matrix with named rows and columns: header "row,<columns...>", then one named row each.
void write_named_matrix(std::ofstream out, const Eigen::MatrixXd& m, const std::vector<std::string>& rows,
                        const std::vector<std::string>& columns) {
  out << "row";
  for (const std::string& column : columns) out << "," << column;
  out << "\n";
  for (Eigen::Index r = 0; r < m.rows(); ++r) {
    out << rows[static_cast<std::size_t>(r)];
    for (Eigen::Index c = 0; c < m.cols(); ++c) out << fmt::format(",{:.17g}", m(r, c));
    out << "\n";
  }
}

}  // namespace

LinearizeSummary linearize_mechanism(const multibody::Model& model, const multibody::AssemblyOptions& assembly,
                                     const LinearizeSettings& settings) {
  const auto wall_start = std::chrono::steady_clock::now();
  // A reference body the model lacks is bad input, before any work.
  if (!settings.reference_body.empty()) reference_body_index(model, settings.reference_body);
  LinearizeSummary summary;
  const auto finish = [&](bool ok) {
    summary.ok = ok;
    summary.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
    return summary;
  };
  // The assembled start at t = 0, and its equilibrium when asked.
  summary.start = prepare_start(model, assembly);
  if (summary.start.assembly.status != multibody::AssemblyStatus::kOk) {
    summary.failure = "assembly";
    summary.message = "assembly failed: " + summary.start.assembly.message;
    return finish(false);
  }
  if (!summary.start.lost_at_singular_start.empty()) {
    summary.failure = "singular start";
    summary.message = fmt::format(
        "the constraints are singular at the linearization point: equation(s) {} depend on the "
        "others here but not next to it, so the motions the joints allow are not known to first "
        "order; move the start slightly off this configuration",
        fmt::join(summary.start.lost_at_singular_start, ", "));
    return finish(false);
  }
  summary.point = summary.start.state;
  if (settings.statics) {
    summary.statics = multibody::solve_statics(model, summary.start.partition, summary.start.state);
    if (summary.statics->status != multibody::StaticsStatus::kOk) {
      summary.failure = "statics";
      summary.message = summary.statics->message;
      return finish(false);
    }
    summary.point = summary.statics->state;
  }
  return finish(linearize_about(model, summary.start.partition, summary.point, settings, summary));
}

bool linearize_about(const multibody::Model& model, const multibody::ConstraintPartition& partition,
                     const multibody::State& point, const LinearizeSettings& settings, LinearizeSummary& summary) {
  const int reference = settings.reference_body.empty() ? -1 : reference_body_index(model, settings.reference_body);
  summary.point = point;
  // Tangent matrices, the joints' free motions, the system modes.
  if (multibody::tangent_matrices(model, partition, point, summary.tangent, summary.message) !=
      multibody::LinearizationStatus::kOk) {
    summary.failure = "singular constraints";
    return false;
  }
  summary.null_space = multibody::null_space_basis(summary.tangent.G, model.nv);
  summary.free_motions = static_cast<int>(summary.null_space.cols());
  summary.modes = multibody::system_modes(summary.tangent, summary.null_space, settings.zero_threshold_hz);
  summary.state_space = multibody::state_space(model, point, summary.tangent, summary.null_space, settings.inputs,
                                               settings.outputs);
  // Mass properties of the whole mechanism (about the ground origin), the held modes.
  const Eigen::MatrixXd Psi = multibody::rigid_motion_basis(model, point, Eigen::Vector3d::Zero());
  summary.mass = multibody::mass_properties(Psi.transpose() * summary.tangent.M * Psi, Eigen::Vector3d::Zero());
  if (reference >= 0) {
    summary.cantilevered =
        multibody::cantilevered_modes(model, point, summary.tangent, reference, settings.zero_threshold_hz);
  }
  return true;
}

const char* linearization_point_kind(const LinearizeSummary& summary) {
  return summary.statics ? "statics" : summary.at >= 0.0 ? "run" : "assembly";
}

std::vector<std::string> coordinate_names(const multibody::Model& model) {
  static const char* kFrame[] = {"vx", "vy", "vz", "wx", "wy", "wz"};
  std::vector<std::string> names;
  for (const multibody::Body& body : model.bodies) {
    for (int k = 0; k < body.nv; ++k) {
      names.push_back(k < 6 ? body.name + "." + kFrame[k] : fmt::format("{}.eta{}", body.name, k - 5));
    }
  }
  return names;
}

std::vector<std::filesystem::path> write_linear_csv(const multibody::Model& model, const LinearizeSummary& summary,
                                                    const std::filesystem::path& directory) {
  std::filesystem::create_directories(directory);
  std::vector<std::filesystem::path> paths;
  const auto open = [&](const char* name) {
    paths.push_back(directory / name);
    std::ofstream out(paths.back());
    if (!out) throw InputError(fmt::format("cannot write {}", paths.back().string()));
    return out;
  };
  const multibody::SystemModes& modes = summary.modes;
  {
    std::ofstream out = open("linear_modes.csv");
    out << "mode,frequency_hz,damping_ratio,undamped_hz,rigid\n";
    for (Eigen::Index i = 0; i < modes.frequencies_hz.size(); ++i) {
      const bool rigid = modes.frequencies_hz(i) == 0.0;
      out << fmt::format("{},{:.10g},{:.6g},{:.10g},{}\n", i + 1, modes.frequencies_hz(i), modes.damping(i),
                         modes.undamped_hz(i), rigid ? 1 : 0);
    }
  }
  {
    std::ofstream out = open("mode_shapes.csv");
    out << "coordinate";
    for (Eigen::Index i = 0; i < modes.shapes.cols(); ++i) out << ",mode" << i + 1;
    out << "\n";
    const std::vector<std::string> names = coordinate_names(model);
    for (Eigen::Index r = 0; r < modes.shapes.rows(); ++r) {
      out << names[static_cast<std::size_t>(r)];
      for (Eigen::Index i = 0; i < modes.shapes.cols(); ++i) out << fmt::format(",{:.10g}", modes.shapes(r, i));
      out << "\n";
    }
  }
  {
    std::ofstream out = open("mass_properties.csv");
    const multibody::MassProperties& m = summary.mass;
    out << "quantity,value,unit\n" << fmt::format("mass,{:.10g},kg\n", m.mass);
    for (int k = 0; k < 3; ++k) out << fmt::format("com_{},{:.10g},m\n", "xyz"[k], m.com_W(k));
    for (int r = 0; r < 3; ++r) {
      for (int c = r; c < 3; ++c) {
        out << fmt::format("I_{}{},{:.10g},kg m^2\n", "xyz"[r], "xyz"[c], m.inertia_com_W(r, c));
      }
    }
  }
  // The state-space matrices (full precision: a controller design reads them back).
  const multibody::StateSpace& ss = summary.state_space;
  write_named_matrix(open("state_space_A.csv"), ss.A, ss.state_names, ss.state_names);
  write_named_matrix(open("state_space_B.csv"), ss.B, ss.state_names, ss.input_names);
  write_named_matrix(open("state_space_C.csv"), ss.C, ss.output_names, ss.state_names);
  write_named_matrix(open("state_space_D.csv"), ss.D, ss.output_names, ss.input_names);
  if (summary.cantilevered) {
    const multibody::CantileveredModes& c = *summary.cantilevered;
    std::ofstream out = open("cantilevered_modes.csv");
    static const char* kDir[] = {"T1", "T2", "T3", "R1", "R2", "R3"};
    out << "mode,frequency_hz,damping_ratio";
    for (const char* d : kDir) out << ",L_" << d;
    for (const char* d : kDir) out << ",meff_" << d;
    for (const char* d : kDir) out << ",fraction_" << d;
    out << "\n";
    for (Eigen::Index i = 0; i < c.modes.frequencies_hz.size(); ++i) {
      out << fmt::format("{},{:.10g},{:.6g}", i + 1, c.modes.frequencies_hz(i), c.modes.damping(i));
      for (int d = 0; d < 6; ++d) out << fmt::format(",{:.10g}", c.participation(i, d));
      for (int d = 0; d < 6; ++d) out << fmt::format(",{:.10g}", c.effective_mass(i, d));
      for (int d = 0; d < 6; ++d) out << fmt::format(",{:.6g}", c.effective_mass(i, d) / c.rigid_mass(d, d));
      out << "\n";
    }
  }
  return paths;
}

}  // namespace limber::run
