// limber_study_deployed_frequencies: the deployed satellite's linearized frequencies (`limber
// linearize --at 6`, docs/linearize.md) against a second method, the spectrum of a free-decay
// run of the full nonlinear model (issue 30: within 1 %).
//
// The run: cases/satellite_deployment.yaml edited in memory — a bus marker and a small impulse
// on it at 6 s (a 20 ms triangle of 20 N along z and 2 N m about x: 0.2 N s and 0.02 N m s,
// which shakes the wings in and out of phase), run to T_END (default 36 s) with the case's own
// integrator. Signals from 6 s on, every 2 ms: each panel's rotation relative to the bus
// (log(R_busᵀ R_panel), 3 components) and its modal coordinates, each with its mean removed
// and scaled to unit RMS; a window, zero-padded FFT (Eigen's), the channels' power summed.
// Each linearized elastic frequency below F_MAX (default 30 Hz) is matched to the nearest local
// maximum of that spectrum (parabolic peak interpolation on the log power), and to that of the
// same estimator run on the state-space model's own response to the impulse (its check: the
// same channels, the relative rotations to first order R_rel0 δθ_panel − δθ_bus).
// The window: Hann (symmetric, zero at both ends) or, with `falling`, the falling half of one
// (cos²(π t / 2T): one at the impulse, zero at the end of the record), the usual window for a
// free decay (impact testing), which keeps the first second where strongly damped modes live.
// Not a test (it runs the satellite for T_END s of simulated time): prints the table of
// docs/linearize.md. Usage: limber_study_deployed_frequencies [T_END] [F_MAX] [OPTION...]
// with options sharp (the latches' damping share a step, damping_depth 0, to test whether the
// share's dependence on the penetration is what moves the strongly damped modes), falling (the
// window above) and linear (the linear response's check only, without the nonlinear run).
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <Eigen/Geometry>
#include <unsupported/Eigen/FFT>
#include <unsupported/Eigen/MatrixFunctions>

#include "io/case_reader.h"
#include "io/case_reduction.h"
#include "io/mechanism_builder.h"
#include "multibody/body.h"
#include "run/linearize_at.h"
#include "run/run_driver.h"

namespace {

using namespace limber;

constexpr double kLinearizeAt = 6.0;     // [s]: the latches locked, as docs/linearize.md
constexpr double kSignalInterval = 2e-3;  // [s]: every second 1 ms sample
double kRecord = 30.0;                    // [s] from kLinearizeAt: T_END − 6
bool kFallingWindow = false;              // the falling half-cosine instead of Hann
constexpr const char* kPanels[] = {"panel_R1", "panel_R2", "panel_L1", "panel_L2"};

// The case text with `what` inserted before `before` (which must be there).
std::string inserted(std::string text, const std::string& before, const std::string& what) {
  const std::size_t at = text.find(before);
  if (at == std::string::npos) throw std::runtime_error("not in the case: " + before);
  return text.insert(at, what);
}

std::string edited_case(const std::string& path, double t_end, bool sharp) {
  std::ifstream file(path);
  std::stringstream text;
  text << file.rdbuf();
  std::string edited = inserted(text.str(), "joints:\n", "markers:\n  bus_center: {body: bus}\n\n");
  edited = inserted(edited, "  spring_R3:",
                    fmt::format("  impulse: {{type: point_load, marker: bus_center, force: [0, 0, 20], torque: [2, 0, 0],\n"
                                "            scale: {{type: table, x: [{0}, {1}, {2}], y: [0, 1, 0]}}}}\n",
                                kLinearizeAt, kLinearizeAt + 0.01, kLinearizeAt + 0.02));
  for (std::size_t depth = edited.find("damping_depth: 1.0e-3"); sharp && depth != std::string::npos;
       depth = edited.find("damping_depth: 1.0e-3")) {
    edited.replace(depth, 21, "damping_depth: 0");
  }
  const std::size_t at = edited.find("t_end: 6.0");
  if (at == std::string::npos) throw std::runtime_error("no t_end: 6.0 in the case");
  return edited.replace(at, 10, fmt::format("t_end: {}", t_end));
}

// Local maxima of `power` (frequencies `f`), each refined by a parabola through log power.
std::vector<double> spectrum_peaks(const std::vector<double>& f, const std::vector<double>& power, double floor) {
  std::vector<double> peaks;
  for (std::size_t k = 1; k + 1 < power.size(); ++k) {
    if (power[k] <= power[k - 1] || power[k] < power[k + 1] || power[k] < floor) continue;
    const double a = std::log(power[k - 1]), b = std::log(power[k]), c = std::log(power[k + 1]);
    const double shift = 0.5 * (a - c) / (a - 2 * b + c);
    peaks.push_back(f[k] + shift * (f[1] - f[0]));
  }
  return peaks;
}

// The local maxima of the summed power spectrum of `channels` (sampled kSignalInterval apart):
// each channel without its mean, scaled to unit RMS, windowed (Hann or falling), zero-padded FFT.
std::vector<double> summed_spectrum_peaks(std::vector<std::vector<double>> channels) {
  const std::size_t n = channels.front().size();
  std::size_t nfft = 1;
  while (nfft < 64 * n) nfft *= 2;
  Eigen::FFT<double> fft;
  std::vector<double> power(nfft / 2, 0.0), f(nfft / 2);
  for (std::size_t k = 0; k < f.size(); ++k) f[k] = k / (nfft * kSignalInterval);
  for (std::vector<double>& x : channels) {
    double mean = 0.0, rms = 0.0;
    for (double v : x) mean += v / n;
    for (double v : x) rms += (v - mean) * (v - mean) / n;
    if (rms <= 0.0) continue;
    std::vector<double> padded(nfft, 0.0);
    for (std::size_t i = 0; i < n; ++i) {
      const double window = kFallingWindow ? 0.5 + 0.5 * std::cos(M_PI * i / (n - 1))
                                           : 0.5 - 0.5 * std::cos(2.0 * M_PI * i / (n - 1));
      padded[i] = window * (x[i] - mean) / std::sqrt(rms);
    }
    std::vector<std::complex<double>> spectrum;
    fft.fwd(spectrum, padded);
    for (std::size_t k = 0; k < power.size(); ++k) power[k] += std::norm(spectrum[k]);
  }
  const double largest = *std::max_element(power.begin() + static_cast<long>(0.5 / f[1]), power.end());
  return spectrum_peaks(f, power, 1e-6 * largest);
}

// The estimator's own check: the state-space model's response to the same impulse (its inputs
// the bus force and torque; x(0+) = B J with J = 0.2 N s along z, 0.02 N m s about x), in the
// nonlinear record's channels over the same record: per panel its rotation relative to the bus
// to first order, R_rel0 δθ_panel − δθ_bus (bus axes; ξ's rotations are in body axes), and its
// modal coordinates (rows of ξ = Z y).
std::vector<std::vector<double>> linear_response(const run::LinearizeSummary& linear, const multibody::Model& model) {
  const multibody::StateSpace& ss = linear.state_space;
  Eigen::VectorXd impulse = Eigen::VectorXd::Zero(6);
  impulse(2) = 0.2;   // force.z
  impulse(3) = 0.02;  // torque.x
  Eigen::VectorXd x = ss.B * impulse;
  const Eigen::MatrixXd step = (ss.A * kSignalInterval).exp();
  const Eigen::Index n = linear.null_space.cols();
  const auto orientation = [&](int body) {
    multibody::FrameKinematics X;
    multibody::body_frame_kinematics(model, body, Eigen::Vector3d::Zero(), Eigen::Matrix3d::Identity(),
                                     linear.point.q, nullptr, X);
    return X.R_WF;
  };
  const multibody::Body& bus = model.bodies[static_cast<std::size_t>(model.find_body("bus"))];
  const Eigen::Matrix3d R_bus = orientation(model.find_body("bus"));
  std::vector<std::vector<double>> channels;
  const int samples = static_cast<int>(std::lround(kRecord / kSignalInterval)) + 1;
  for (int i = 0; i < samples; ++i) {
    const Eigen::VectorXd xi = linear.null_space * x.head(n);
    std::vector<double> values;
    for (const char* name : kPanels) {
      const int p = model.find_body(name);
      const multibody::Body& panel = model.bodies[static_cast<std::size_t>(p)];
      const Eigen::Vector3d turn = R_bus.transpose() * orientation(p) * xi.segment<3>(panel.v_offset + 3) -
                                   xi.segment<3>(bus.v_offset + 3);
      for (int k = 0; k < 3; ++k) values.push_back(turn(k));
      for (int k = 6; k < panel.nv; ++k) values.push_back(xi(panel.v_offset + k));
    }
    if (channels.empty()) channels.resize(values.size());
    for (std::size_t c = 0; c < values.size(); ++c) channels[c].push_back(values[c]);
    x = step * x;
  }
  return channels;
}

}  // namespace

int main(int argc, char** argv) {
  const double t_end = argc > 1 ? std::atof(argv[1]) : 36.0;
  kRecord = t_end - kLinearizeAt;
  const double f_max = argc > 2 ? std::atof(argv[2]) : 30.0;
  const std::string path = std::string(LIMBER_CASES_DIR) + "/satellite_deployment.yaml";
  bool sharp = false, linear_only = false;
  for (int a = 3; a < argc; ++a) {
    const std::string option = argv[a];
    sharp = sharp || option == "sharp";
    kFallingWindow = kFallingWindow || option == "falling";
    linear_only = linear_only || option == "linear";
  }
  const io::Case input = io::read_case_text(edited_case(path, t_end, sharp), path);
  const io::Mechanism mechanism =
      io::build_mechanism(input, io::reduce_case(input, io::ReductionScope::kMechanismBodies));
  const multibody::Model& model = mechanism.model;

  // The linearized frequencies at 6 s (the impulse starts there: zero at the point).
  run::LinearizeSettings settings;
  settings.zero_threshold_hz = 0.5;
  int bus_center = 0;
  while (model.markers[static_cast<std::size_t>(bus_center)].name != "bus_center") ++bus_center;
  settings.inputs = {{"force", multibody::LinearInputKind::kForce, bus_center, -1, multibody::ChannelAxes::kGround},
                     {"torque", multibody::LinearInputKind::kTorque, bus_center, -1, multibody::ChannelAxes::kGround}};
  const run::LinearizeSummary linear = run::linearize_at(model, mechanism.assembly, mechanism.run, kLinearizeAt, settings);
  if (!linear.ok) {
    fmt::print(stderr, "linearization failed: {}\n", linear.message);
    return 2;
  }

  const std::vector<double> linear_peaks = summed_spectrum_peaks(linear_response(linear, model));
  // The free decay: panel rotations relative to the bus and modal coordinates from 6 s on.
  const int bus = model.find_body("bus");
  std::vector<int> panels;
  for (const char* name : kPanels) panels.push_back(model.find_body(name));
  std::vector<std::vector<double>> channels;
  double next = kLinearizeAt;
  run::RunHooks hooks;
  hooks.on_sample = [&](const integrate::Sample& s, const results::Sample&) {
    if (s.t < next - 1e-9) return;
    next += kSignalInterval;
    std::vector<double> values;
    multibody::FrameKinematics X_bus, X_panel;
    multibody::body_frame_kinematics(model, bus, Eigen::Vector3d::Zero(), Eigen::Matrix3d::Identity(), s.q, nullptr,
                                     X_bus);
    for (const int p : panels) {
      multibody::body_frame_kinematics(model, p, Eigen::Vector3d::Zero(), Eigen::Matrix3d::Identity(), s.q, nullptr,
                                       X_panel);
      const Eigen::AngleAxisd turn(Eigen::Matrix3d(X_bus.R_WF.transpose() * X_panel.R_WF));
      for (int k = 0; k < 3; ++k) values.push_back(turn.angle() * turn.axis()(k));
      const multibody::Body& body = model.bodies[static_cast<std::size_t>(p)];
      for (int m = 7; m < body.nq; ++m) values.push_back(s.q(body.q_offset + m));
    }
    if (channels.empty()) channels.resize(values.size());
    for (std::size_t c = 0; c < values.size(); ++c) channels[c].push_back(values[c]);
  };
  const run::RunSummary ran = linear_only ? run::RunSummary{} : run::run_mechanism(model, mechanism.assembly, mechanism.run, hooks);
  if (!linear_only && !ran.ok) {
    fmt::print(stderr, "run failed at {} s: {}\n", ran.t_reached, ran.message);
    return 2;
  }

  const std::vector<double> peaks = linear_only ? std::vector<double>{} : summed_spectrum_peaks(channels);
  const std::size_t n = static_cast<std::size_t>(std::lround(kRecord / kSignalInterval)) + 1;

  fmt::print("deployed satellite: linearized at t = {} s against the free decay {} to {} s ({} samples, "
             "resolution 1/T = {:.3f} Hz, {} window{}), run {:.0f} s wall\n",
             kLinearizeAt, kLinearizeAt, t_end, n, 1.0 / (t_end - kLinearizeAt), kFallingWindow ? "falling" : "Hann",
             linear_only ? ", no nonlinear run" : "", ran.wall_seconds);
  fmt::print("{:>4} {:>12} {:>10} {:>14} {:>10} {:>20} {:>10}\n", "mode", "linear [Hz]", "damping", "spectrum [Hz]",
             "diff [%]", "linear response [Hz]", "diff [%]");
  double worst = 0.0;
  for (Eigen::Index i = 0; i < linear.modes.frequencies_hz.size(); ++i) {
    const double fl = linear.modes.frequencies_hz(i);
    if (fl <= 0.0 || fl > f_max) continue;
    const auto nearest = [&](const std::vector<double>& candidates) {
      double best = 0.0;
      for (double p : candidates) {
        if (std::abs(p - fl) < std::abs(best - fl)) best = p;
      }
      return best;
    };
    const double run_peak = nearest(peaks), linear_peak = nearest(linear_peaks);
    const double diff = linear_only ? std::nan("") : 100.0 * (run_peak - fl) / fl;
    if (!linear_only) worst = std::max(worst, std::abs(diff));
    fmt::print("{:>4} {:>12.4f} {:>10.4f} {:>14.4f} {:>10.3f} {:>20.4f} {:>10.3f}\n", i + 1, fl, linear.modes.damping(i),
               run_peak, diff, linear_peak, 100.0 * (linear_peak - fl) / fl);
  }
  fmt::print("largest difference: {:.3f} %\n", worst);
  return 0;
}
