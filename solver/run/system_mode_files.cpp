#include "run/system_mode_files.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include <fmt/format.h>

#include "integrate/integrator.h"
#include "multibody/constraints.h"
#include "multibody/linearization.h"
#include "run/sample_record.h"

namespace limber::run {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// A of the header: the largest marker displacement amplitude_fraction of the size, and no
// body's rotation above kMaxModeRotation.
double mode_amplitude(const multibody::Model& model, const multibody::Workspace& ws, const Eigen::VectorXd& q,
                      const Eigen::VectorXd& shape, double amplitude_fraction) {
  Eigen::Vector3d low = Eigen::Vector3d::Constant(kInfinity), high = -low;
  double largest_move = 0.0, largest_turn = 0.0;
  for (const multibody::FrameKinematics& marker : ws.markers) {
    low = low.cwiseMin(marker.p_W);
    high = high.cwiseMax(marker.p_W);
    largest_move = std::max(largest_move, (marker.J_p * shape).norm());
  }
  for (const multibody::Body& body : model.bodies) {
    if (body.nv == 0) continue;
    low = low.cwiseMin(q.segment<3>(body.q_offset));
    high = high.cwiseMax(q.segment<3>(body.q_offset));
    largest_move = std::max(largest_move, shape.segment<3>(body.v_offset).norm());
    largest_turn = std::max(largest_turn, shape.segment<3>(body.v_offset + 3).norm());
  }
  const double size = (high - low).norm();
  double A = kInfinity;
  if (largest_move > 0.0 && size > 0.0) A = amplitude_fraction * size / largest_move;
  if (largest_turn > 0.0) A = std::min(A, kMaxModeRotation / largest_turn);
  return std::isfinite(A) ? A : 0.0;  // a mode that moves nothing drawn (a modal body's alone)
}

}  // namespace

std::vector<std::filesystem::path> write_system_mode_files(const multibody::Model& model, const LinearizeSummary& summary,
                                                           const std::filesystem::path& directory,
                                                           const std::string& title, const std::string& case_file,
                                                           const SystemModeFileOptions& options) {
  std::vector<std::filesystem::path> paths;
  const multibody::SystemModes& modes = summary.modes;
  const multibody::State& point = summary.point;
  multibody::Workspace ws(model);
  multibody::update_marker_kinematics(model, point, multibody::Stage::kPosition, ws);
  std::vector<unsigned char> engaged = point.engaged;
  engaged.resize(model.forces.size(), 0);
  for (Eigen::Index k = 0; k < modes.frequencies_hz.size() && static_cast<int>(paths.size()) < options.modes; ++k) {
    const double f = modes.undamped_hz(k);
    if (f <= 0.0) continue;  // rigid (no period) or unstable (no oscillation)
    const Eigen::VectorXd shape = modes.shapes.col(k);
    const double A = mode_amplitude(model, ws, point.q, shape, options.amplitude_fraction);
    const double w = 2.0 * std::numbers::pi * f;

    // One period at rest about the point, every body in the mode's motion.
    const std::filesystem::path mode_directory = directory / "system_modes" / fmt::format("mode_{:02d}", k + 1);
    results::ResultsWriter writer(mode_directory,
                                  fmt::format("{}: system mode {} at {:.6g} Hz (amplitude {:.3g})", title, k + 1, f, A),
                                  case_file);
    declare_model(model, writer);
    writer.set_integrator("linear mode");
    SampleRecorder recorder(model, summary.start.partition, engaged);
    integrate::Sample sample;
    sample.lambda = summary.tangent.lambda;
    sample.integrals = Eigen::VectorXd::Zero(kEnergyIntegrals);
    for (int i = 0; i <= options.frames; ++i) {
      const double t = i / (f * options.frames);
      sample.t = t;
      sample.q = multibody::displaced_coordinates(model, point.q, A * std::sin(w * t) * shape);
      sample.v = A * w * std::cos(w * t) * shape;
      sample.vdot = -A * w * w * std::sin(w * t) * shape;
      writer.append_sample(recorder.record(sample));
    }
    writer.finish(results::RunStatus::kOk);
    paths.push_back(writer.path());
  }
  return paths;
}

}  // namespace limber::run
