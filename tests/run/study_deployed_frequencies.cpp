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
// Option pencil replaces the spectrum: the run is repeated without the impulse and subtracted
// (the impulse's own response, without the deployment's residual ringing), the linear model is
// driven by the same 20 ms triangle (not an ideal impulse), the two are compared sample by
// sample, and the poles of both come from the matrix pencil (matrix_pencil.h) over the first
// RECORD s (record=RECORD, default 1.5) from the load's end; floor=F (default 1e-7) is the
// pencil's singular-value floor and weight=W (1e-3) the least weight of a pole matched. With
// it, amp=A scales the impulse (linearity: the difference's second-order part goes with A) and
// step=H replaces the run's 5e-4 s step.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdlib>
#include <iterator>
#include <string>
#include <vector>

#include <Eigen/Geometry>
#include <unsupported/Eigen/FFT>
#include <unsupported/Eigen/MatrixFunctions>

#include "io/case_reader.h"
#include "multibody/body.h"
#include "run/linearize_at.h"
#include "run/run_driver.h"
#include "matrix_pencil.h"
#include "satellite_study.h"

namespace {

using namespace limber;

constexpr double kLinearizeAt = 6.0;     // [s]: the latches locked, as docs/linearize.md
constexpr double kSignalInterval = 2e-3;  // [s]: every second 1 ms sample
double kRecord = 30.0;                    // [s] from kLinearizeAt: T_END − 6
bool kFallingWindow = false;              // the falling half-cosine instead of Hann
const auto& kPanels = study::kSatellitePanels;

std::string edited_case(double t_end, bool sharp, double amplitude = 1.0, const std::string& step = "") {
  const std::string impulse = fmt::format(
      "  impulse: {{type: point_load, marker: bus_center, force: [0, 0, {3}], torque: [{4}, 0, 0],\n"
      "            scale: {{type: table, x: [{0}, {1}, {2}], y: [0, 1, 0]}}}}\n",
      kLinearizeAt, kLinearizeAt + 0.01, kLinearizeAt + 0.02, 20.0 * amplitude, 2.0 * amplitude);
  return study::satellite_case_text(t_end, impulse, step, sharp);
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

void append(std::vector<std::vector<double>>& channels, const std::vector<double>& values) {
  if (channels.empty()) channels.resize(values.size());
  for (std::size_t c = 0; c < values.size(); ++c) channels[c].push_back(values[c]);
}

int record_samples() { return static_cast<int>(std::lround(kRecord / kSignalInterval)) + 1; }

// The estimator's own check: the state-space model's response to the same impulse (its inputs
// the bus force and torque; x(0+) = B J with J = 0.2 N s along z, 0.02 N m s about x), in the
// nonlinear record's channels over the same record.
std::vector<std::vector<double>> linear_response(const run::LinearizeSummary& linear, const multibody::Model& model) {
  const multibody::StateSpace& ss = linear.state_space;
  Eigen::VectorXd impulse = Eigen::VectorXd::Zero(6);
  impulse(2) = 0.2;   // force.z
  impulse(3) = 0.02;  // torque.x
  Eigen::VectorXd x = ss.B * impulse;
  const Eigen::MatrixXd step = (ss.A * kSignalInterval).exp();
  const study::LinearPanelChannels channels_of(linear, model);
  std::vector<std::vector<double>> channels;
  for (int i = 0; i < record_samples(); ++i) {
    append(channels, channels_of(x));
    x = step * x;
  }
  return channels;
}

// The state-space model's response to the run's own load: the 20 ms triangle (peak 20 A N
// along z, 2 A N m about x at 10 ms), in substeps of h = 0.1 ms with the load at each one's
// middle (x ← e^{Ah} x + e^{Ah/2} B u h: error O(h²), (ωh)² = 1e-4 at 16.6 Hz), then e^{A Δt}
// from sample to sample.
std::vector<std::vector<double>> linear_triangle_response(const run::LinearizeSummary& linear,
                                                          const multibody::Model& model, double amplitude) {
  const multibody::StateSpace& ss = linear.state_space;
  constexpr int kSubsteps = 20;             // per sample interval: h = 0.1 ms
  constexpr int kLoadedIntervals = 10;      // the triangle's 20 ms
  const double h = kSignalInterval / kSubsteps, duration = kLoadedIntervals * kSignalInterval;
  const Eigen::MatrixXd substep = (ss.A * h).exp(), half = (ss.A * (0.5 * h)).exp();
  const Eigen::MatrixXd step = (ss.A * kSignalInterval).exp();
  Eigen::VectorXd peak = Eigen::VectorXd::Zero(6);
  peak(2) = 20.0 * amplitude;  // force.z [N]
  peak(3) = 2.0 * amplitude;   // torque.x [N m]
  const Eigen::MatrixXd B_peak = ss.B * peak;
  const auto triangle = [&](double t) { return std::max(0.0, 1.0 - std::abs(t - 0.5 * duration) / (0.5 * duration)); };
  const study::LinearPanelChannels channels_of(linear, model);
  std::vector<std::vector<double>> channels;
  Eigen::VectorXd x = Eigen::VectorXd::Zero(ss.A.rows());
  for (int i = 0; i < record_samples(); ++i) {
    append(channels, channels_of(x));
    if (i >= kLoadedIntervals) {
      x = step * x;
      continue;
    }
    for (int j = 0; j < kSubsteps; ++j) {
      x = substep * x + half * B_peak * (h * triangle((i * kSubsteps + j + 0.5) * h));
    }
  }
  return channels;
}

// The run's channels from 6 s on, every kSignalInterval: per panel its rotation relative to the
// bus (log(R_busᵀ R_panel)) and its modal coordinates.
std::vector<std::vector<double>> run_channels(const io::Mechanism& mechanism, run::RunSummary& ran) {
  const multibody::Model& model = mechanism.model;
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
    append(channels, values);
  };
  ran = run::run_mechanism(model, mechanism.assembly, mechanism.run, hooks);
  return channels;
}

// Option pencil: the impulse's own response (the run less the run without the impulse) against
// the linear model's response to the same triangle, sample by sample and by their poles.
int pencil_study(const io::Mechanism& mechanism, const io::Case& baseline_input, const run::LinearizeSummary& linear,
                 double f_max, double amplitude, double pencil_record, double floor, double min_weight) {
  const io::Mechanism baseline = study::built_mechanism(baseline_input);
  run::RunSummary ran, ran_baseline;
  std::vector<std::vector<double>> response = run_channels(mechanism, ran);
  const std::vector<std::vector<double>> rest = run_channels(baseline, ran_baseline);
  if (!ran.ok || !ran_baseline.ok) {
    fmt::print(stderr, "run failed: {} {}\n", ran.message, ran_baseline.message);
    return 2;
  }
  const std::vector<std::vector<double>> linear_channels = linear_triangle_response(linear, mechanism.model, amplitude);
  // Both over the same samples from the load's end on (20 ms: a free decay from there), each
  // channel weighed by the linear response's RMS; channels the linear response leaves at rest
  // (below 1e-6 of the largest RMS of their kind, by symmetry) are left out.
  constexpr std::size_t kLoadEnd = 10;
  const std::size_t n = std::min({response.front().size(), rest.front().size(), linear_channels.front().size()});
  const std::size_t n_pencil = std::min(n - kLoadEnd, static_cast<std::size_t>(std::lround(pencil_record / kSignalInterval)));
  std::vector<double> rms(response.size(), 0.0);
  double largest_turn = 0.0, largest_modal = 0.0;
  const std::size_t per_panel = response.size() / std::size(kPanels);
  for (std::size_t c = 0; c < response.size(); ++c) {
    for (std::size_t k = 0; k < n; ++k) rms[c] += linear_channels[c][k] * linear_channels[c][k] / n;
    rms[c] = std::sqrt(rms[c]);
    (c % per_panel < 3 ? largest_turn : largest_modal) = std::max(c % per_panel < 3 ? largest_turn : largest_modal, rms[c]);
  }
  std::vector<std::vector<double>> run_weighed, linear_weighed;
  double difference = 0.0, norm = 0.0, difference_first = 0.0, norm_first = 0.0;
  for (std::size_t c = 0; c < response.size(); ++c) {
    if (rms[c] < 1e-6 * (c % per_panel < 3 ? largest_turn : largest_modal)) continue;
    run_weighed.emplace_back();
    linear_weighed.emplace_back();
    double d_c = 0.0, l_c = 0.0;
    for (std::size_t k = kLoadEnd; k < n; ++k) {
      const double r = (response[c][k] - rest[c][k]) / rms[c], l = linear_channels[c][k] / rms[c];
      if (k < kLoadEnd + n_pencil) {
        run_weighed.back().push_back(r);
        linear_weighed.back().push_back(l);
        difference_first += (r - l) * (r - l);
        norm_first += l * l;
      }
      difference += (r - l) * (r - l);
      norm += l * l;
      d_c += (r - l) * (r - l);
      l_c += l * l;
    }
    fmt::print("channel {:2d} ({} {:2d}): linear RMS {:.3e}, |run - linear| / |linear| = {:.4f}\n", c,
               kPanels[c / per_panel], static_cast<int>(c % per_panel), rms[c], std::sqrt(d_c / l_c));
  }
  const auto poles_run = study::pencil_poles(run_weighed, static_cast<Eigen::Index>(n_pencil), kSignalInterval, floor);
  const auto poles_linear =
      study::pencil_poles(linear_weighed, static_cast<Eigen::Index>(n_pencil), kSignalInterval, floor);
  fmt::print("deployed satellite: the impulse's response (x {}) run less the run without it, {} to {} s, against "
             "the linear model's response to the same load; runs {:.0f} s + {:.0f} s wall\n",
             amplitude, kLinearizeAt, kLinearizeAt + kRecord, ran.wall_seconds, ran_baseline.wall_seconds);
  fmt::print("sample by sample, channels weighed by the linear RMS: |run - linear| / |linear| = {:.4f} over {} s, "
             "{:.4f} over the first {} s\n",
             std::sqrt(difference / norm), kRecord, std::sqrt(difference_first / norm_first), pencil_record);
  fmt::print("matrix pencil over the first {} s ({} samples, {} and {} poles):\n", pencil_record, n_pencil,
             poles_run.size(), poles_linear.size());
  fmt::print("{:>4} {:>12} {:>9} {:>14} {:>9} {:>9} {:>14} {:>9} {:>9}\n", "mode", "linear [Hz]", "zeta",
             "run pencil", "zeta", "diff [%]", "lin. pencil", "zeta", "diff [%]");
  double worst = 0.0;
  for (Eigen::Index i = 0; i < linear.modes.frequencies_hz.size(); ++i) {
    const double fl = linear.modes.frequencies_hz(i), zl = linear.modes.damping(i);
    if (fl <= 0.0 || fl > f_max) continue;
    const std::complex<double> s(-zl * 2 * M_PI * fl, 2 * M_PI * fl * std::sqrt(std::max(0.0, 1 - zl * zl)));
    const study::PencilPole pr = study::nearest_pole(poles_run, s, min_weight);
    const study::PencilPole pl = study::nearest_pole(poles_linear, s, min_weight);
    const double fr = std::abs(pr.s) / (2 * M_PI), fp = std::abs(pl.s) / (2 * M_PI);
    worst = std::max(worst, std::abs(100.0 * (fr - fl) / fl));
    fmt::print("{:>4} {:>12.4f} {:>9.4f} {:>14.4f} {:>9.4f} {:>9.3f} {:>14.4f} {:>9.4f} {:>9.3f}\n", i + 1, fl, zl, fr,
               -pr.s.real() / std::abs(pr.s), 100.0 * (fr - fl) / fl, fp, -pl.s.real() / std::abs(pl.s),
               100.0 * (fp - fl) / fl);
  }
  fmt::print("largest difference (run pencil): {:.3f} %\n", worst);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  const double t_end = argc > 1 ? std::atof(argv[1]) : 36.0;
  kRecord = t_end - kLinearizeAt;
  const double f_max = argc > 2 ? std::atof(argv[2]) : 30.0;
  const std::string path = std::string(LIMBER_CASES_DIR) + "/satellite_deployment.yaml";  // for messages
  bool sharp = false, linear_only = false, pencil = false;
  double amplitude = 1.0, pencil_record = 1.5, floor = 1e-7, min_weight = 1e-3;
  std::string step;
  for (int a = 3; a < argc; ++a) {
    const std::string option = argv[a];
    sharp = sharp || option == "sharp";
    kFallingWindow = kFallingWindow || option == "falling";
    linear_only = linear_only || option == "linear";
    pencil = pencil || option == "pencil";
    if (option.rfind("amp=", 0) == 0) amplitude = std::atof(option.c_str() + 4);
    if (option.rfind("record=", 0) == 0) pencil_record = std::atof(option.c_str() + 7);
    if (option.rfind("step=", 0) == 0) step = option.substr(5);
    if (option.rfind("floor=", 0) == 0) floor = std::atof(option.c_str() + 6);
    if (option.rfind("weight=", 0) == 0) min_weight = std::atof(option.c_str() + 7);
  }
  const io::Case input = io::read_case_text(edited_case(t_end, sharp, amplitude, step), path);
  const io::Mechanism mechanism = study::built_mechanism(input);
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
  if (pencil) {
    const io::Case baseline = io::read_case_text(edited_case(t_end, sharp, 0.0, step), path);
    return pencil_study(mechanism, baseline, linear, f_max, amplitude, pencil_record, floor, min_weight);
  }

  const std::vector<double> linear_peaks = summed_spectrum_peaks(linear_response(linear, model));
  // The free decay: panel rotations relative to the bus and modal coordinates from 6 s on.
  run::RunSummary ran;
  const std::vector<std::vector<double>> channels = linear_only ? std::vector<std::vector<double>>{}
                                                                : run_channels(mechanism, ran);
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
