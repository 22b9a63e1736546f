// limber_study_deployed_response: the deployed satellite's state-space model (`limber linearize
// --at T`, docs/linearize.md) against the nonlinear run continued from the same state under the
// same load, sample by sample (issue 30: "the state-space model's step response against the
// nonlinear run for a small torque on the bus"), and the measurements behind the docs' account
// of the 1.2 % that was left between the run's impulse response and the linear model's.
//
// The run: cases/satellite_deployment.yaml (satellite_study.h) with a load on the bus from T:
// `load=step` (default) a torque step τ = A (0.02, 0.01, −0.015) N m in ground axes, ramped in
// over 10 ms; `load=impulse` the frequency study's 20 ms triangle (20 A N along z, 2 A N m
// about x at its peak). The run is made twice, with the load and without (A = 0), and the
// second is subtracted: what is left is the load's own response along the run's trajectory,
// which at T is still ringing from the deployment. Channels every 2 ms from T: the bus's
// rotation log(R_bus R_bus,restᵀ) and angular velocity ω − ω_rest (ground axes); per panel its
// rotation relative to the bus as the left increment log(R_rel R_rel,restᵀ) of R_rel = R_busᵀ
// R_panel (first order: R_rel0 δθ_panel − δθ_bus, what the linear model gives; the rotation
// vector's own difference log R_rel − log R_rel,rest is that times the inverse left Jacobian of
// a turn near 90–270°, not the same) and its modal coordinates.
// The linear model: the state space of `--at T` with the bus_center force and torque in and its
// rotation and angular velocity out, driven by the same load shape (zero-order hold on substeps
// of 0.1 ms at their midpoint values: exact for the step's plateau, O(h²) on the ramps), and,
// to tell which of its terms matter, the same linearized about the configuration at T at rest
// (v = 0: no gyroscopic terms, but M v̇0 ≠ 0 still, the configuration not in equilibrium) and
// about the static equilibrium statics finds from it (`limber linearize --at T --statics`).
// Printed per channel group: |run − linear| / |linear| (RMS over the record), the least-squares
// gain run ≈ g · linear and what is left after it, and the least-squares time shift.
// Not a test (two satellite runs): usage limber_study_deployed_response [load=step|impulse]
// [at=T (6)] [record=R (4)] [amp=A (1)] [step=H (the case's 5e-4)].
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

#include <Eigen/Dense>
#include <Eigen/Geometry>
#include <unsupported/Eigen/MatrixFunctions>

#include "run/linearize_at.h"
#include "run/run_driver.h"
#include "satellite_study.h"

namespace {

using namespace limber;
using Channels = std::vector<std::vector<double>>;  // [channel][sample]

constexpr double kInterval = 2e-3;  // [s] between compared samples (every second 1 ms sample)
constexpr int kSubsteps = 20;       // per interval: 0.1 ms
constexpr double kRamp = 0.01;      // [s]: the step's ramp, the impulse's half width

struct Load {
  bool step = true;
  double at = 6.0;
  double amplitude = 1.0;
  Eigen::Vector3d force() const { return step ? Eigen::Vector3d::Zero() : Eigen::Vector3d(0, 0, 20.0 * amplitude); }
  Eigen::Vector3d torque() const {
    return step ? Eigen::Vector3d(0.02, 0.01, -0.015) * amplitude : Eigen::Vector3d(2.0 * amplitude, 0, 0);
  }
  // The scale at time s after T.
  double shape(double s) const {
    if (s <= 0.0) return 0.0;
    return step ? std::min(1.0, s / kRamp) : std::max(0.0, 1.0 - std::abs(s - kRamp) / kRamp);
  }
  // The first compared sample: from the impulse's end (a free decay), from T for the step.
  std::size_t first_sample() const { return step ? 0 : static_cast<std::size_t>(std::lround(2 * kRamp / kInterval)); }
  std::string entry(double t_end) const {
    const Eigen::Vector3d f = force(), tau = torque();
    const std::string table = step ? fmt::format("x: [{}, {}, {}], y: [0, 1, 1]", at, at + kRamp, t_end + 1.0)
                                   : fmt::format("x: [{}, {}, {}], y: [0, 1, 0]", at, at + kRamp, at + 2 * kRamp);
    return fmt::format("  bus_load: {{type: point_load, marker: bus_center, force: [{}, {}, {}], torque: [{}, {}, {}],\n"
                       "            scale: {{type: table, {}}}}}\n",
                       f.x(), f.y(), f.z(), tau.x(), tau.y(), tau.z(), table);
  }
};

// What the run gives at each compared sample.
struct RunRecord {
  std::vector<Eigen::Matrix3d> R_bus;
  std::vector<Eigen::Vector3d> w_bus_W;
  std::vector<std::vector<Eigen::Matrix3d>> R_rel;  // [sample][panel]
  std::vector<std::vector<double>> modal;           // [sample][panel modes, panel by panel]
};

RunRecord record_run(const io::Mechanism& mechanism, double from, bool& ok, double& wall) {
  const multibody::Model& model = mechanism.model;
  const int bus = model.find_body("bus");
  RunRecord record;
  double next = from;
  run::RunHooks hooks;
  hooks.on_sample = [&](const integrate::Sample& s, const results::Sample&) {
    if (s.t < next - 1e-9) return;
    next += kInterval;
    const Eigen::Matrix3d R_bus = study::body_orientation(model, bus, s.q);
    const multibody::Body& bus_body = model.bodies[static_cast<std::size_t>(bus)];
    record.R_bus.push_back(R_bus);
    record.w_bus_W.push_back(R_bus * s.v.segment<3>(bus_body.v_offset + 3));
    record.R_rel.emplace_back();
    record.modal.emplace_back();
    for (const char* name : study::kSatellitePanels) {
      const int p = model.find_body(name);
      record.R_rel.back().push_back(R_bus.transpose() * study::body_orientation(model, p, s.q));
      const multibody::Body& panel = model.bodies[static_cast<std::size_t>(p)];
      for (int m = 7; m < panel.nq; ++m) record.modal.back().push_back(s.q(panel.q_offset + m));
    }
  };
  const run::RunSummary ran = run::run_mechanism(model, mechanism.assembly, mechanism.run, hooks);
  ok = ran.ok;
  wall = ran.wall_seconds;
  if (!ran.ok) fmt::print(stderr, "run failed at {} s: {}\n", ran.t_reached, ran.message);
  return record;
}

Eigen::Vector3d rotation_vector(const Eigen::Matrix3d& R) {
  const Eigen::AngleAxisd turn(R);
  return turn.angle() * turn.axis();
}

// The load's own response: the loaded run less the one without the load, as channel groups
// bus attitude (3), bus rate (3), panel turns (3 per panel), panel modal coordinates.
struct Groups {
  Channels attitude, rate, turns, modal;
};

void push(Channels& channels, std::size_t c, double value) {
  if (channels.size() <= c) channels.resize(c + 1);
  channels[c].push_back(value);
}

Groups run_difference(const RunRecord& loaded, const RunRecord& rest) {
  Groups out;
  const std::size_t n = std::min(loaded.R_bus.size(), rest.R_bus.size());
  for (std::size_t k = 0; k < n; ++k) {
    const Eigen::Vector3d attitude = rotation_vector(loaded.R_bus[k] * rest.R_bus[k].transpose());
    const Eigen::Vector3d rate = loaded.w_bus_W[k] - rest.w_bus_W[k];
    for (int d = 0; d < 3; ++d) {
      push(out.attitude, d, attitude(d));
      push(out.rate, d, rate(d));
    }
    for (std::size_t p = 0; p < loaded.R_rel[k].size(); ++p) {
      const Eigen::Vector3d turn = rotation_vector(loaded.R_rel[k][p] * rest.R_rel[k][p].transpose());
      for (int d = 0; d < 3; ++d) push(out.turns, 3 * p + static_cast<std::size_t>(d), turn(d));
    }
    for (std::size_t m = 0; m < loaded.modal[k].size(); ++m) push(out.modal, m, loaded.modal[k][m] - rest.modal[k][m]);
  }
  return out;
}

// The state-space model's response to the load (inputs force.xyz, torque.xyz; outputs
// attitude.xyz, rate.xyz), zero-order hold per substep: x ← Φ x + Γ u, [Φ Γ] from e^{[A B; 0 0] h}.
Groups linear_response(const run::LinearizeSummary& linear, const multibody::Model& model, const Load& load,
                       std::size_t samples) {
  const multibody::StateSpace& ss = linear.state_space;
  const Eigen::Index nx = ss.A.rows(), nu = ss.B.cols();
  const double h = kInterval / kSubsteps;
  Eigen::MatrixXd augmented = Eigen::MatrixXd::Zero(nx + nu, nx + nu);
  augmented.topLeftCorner(nx, nx) = ss.A * h;
  augmented.topRightCorner(nx, nu) = ss.B * h;
  const Eigen::MatrixXd E = augmented.exp();
  const Eigen::MatrixXd Phi = E.topLeftCorner(nx, nx), Gamma = E.topRightCorner(nx, nu);
  Eigen::VectorXd peak(nu);
  peak << load.force(), load.torque();
  const study::LinearPanelChannels panels(linear, model);
  Groups out;
  Eigen::VectorXd x = Eigen::VectorXd::Zero(nx);
  for (std::size_t k = 0; k < samples; ++k) {
    const Eigen::VectorXd y = ss.C * x + ss.D * (peak * load.shape(k * kInterval));
    for (int d = 0; d < 3; ++d) {
      push(out.attitude, d, y(d));
      push(out.rate, d, y(3 + d));
    }
    const std::vector<double> values = panels(x);
    const std::size_t per_panel = values.size() / std::size(study::kSatellitePanels);
    for (std::size_t c = 0; c < values.size(); ++c) {
      if (c % per_panel < 3) push(out.turns, 3 * (c / per_panel) + c % per_panel, values[c]);
      else push(out.modal, c - 3 * (c / per_panel + 1), values[c]);
    }
    for (int j = 0; j < kSubsteps; ++j) x = Phi * x + Gamma * (peak * load.shape((k * kSubsteps + j + 0.5) * h));
  }
  return out;
}

// Sums over a group's channels and its samples from `first` on: |r − l|² and |l|², the
// least-squares gain g (r ≈ g l) with |r − g l|², and the time shift δ (r ≈ l(t + δ) to first
// order: the least squares of r − l on l̇).
struct Agreement {
  double relative = 0.0, gain = 0.0, after_gain = 0.0, shift = 0.0, rms = 0.0;
};

Agreement agreement(const Channels& run, const Channels& linear, std::size_t first) {
  double dd = 0.0, ll = 0.0, rl = 0.0, rr = 0.0, dl_dot = 0.0, l_dot2 = 0.0;
  std::size_t count = 0;
  for (std::size_t c = 0; c < std::min(run.size(), linear.size()); ++c) {
    const std::size_t n = std::min(run[c].size(), linear[c].size());
    for (std::size_t k = std::max<std::size_t>(first, 1); k + 1 < n; ++k) {
      const double r = run[c][k], l = linear[c][k], l_dot = (linear[c][k + 1] - linear[c][k - 1]) / (2 * kInterval);
      dd += (r - l) * (r - l);
      ll += l * l;
      rl += r * l;
      rr += r * r;
      dl_dot += (r - l) * l_dot;
      l_dot2 += l_dot * l_dot;
      ++count;
    }
  }
  Agreement a;
  if (ll <= 0.0) return a;
  a.relative = std::sqrt(dd / ll);
  a.gain = rl / ll;
  a.after_gain = std::sqrt(std::max(0.0, rr - rl * rl / ll) / ll);
  a.shift = l_dot2 > 0.0 ? dl_dot / l_dot2 : 0.0;
  a.rms = std::sqrt(ll / static_cast<double>(count));
  return a;
}

// The rigid spacecraft's share of a group (the whole mechanism as one body, I_c⁻¹ τ twice
// integrated), to show the elastic part of the bus's response apart.
Channels minus_rigid(Channels channels, const run::LinearizeSummary& linear, const Load& load, bool attitude) {
  const Eigen::Vector3d alpha = linear.mass.inertia_com_W.ldlt().solve(load.torque());
  double rate = 0.0, angle = 0.0;  // ∫shape, ∫∫shape by substeps
  const double h = kInterval / kSubsteps;
  const std::size_t n = channels.front().size();
  for (std::size_t k = 0; k < n; ++k) {
    for (int d = 0; d < 3; ++d) channels[static_cast<std::size_t>(d)][k] -= alpha(d) * (attitude ? angle : rate);
    for (int j = 0; j < kSubsteps; ++j) {
      const double s = load.shape((k * kSubsteps + j + 0.5) * h);
      angle += h * (rate + 0.5 * h * s);
      rate += h * s;
    }
  }
  return channels;
}

void print_row(const char* model_name, const char* group, const Agreement& a, const char* unit) {
  fmt::print("{:<12} {:<16} {:>11.3e} {:>4} {:>10.5f} {:>9.5f} {:>12.5f} {:>10.4f}\n", model_name, group, a.rms, unit,
             a.relative, a.gain, a.after_gain, 1e3 * a.shift);
}

void compare(const char* name, const Groups& nonlinear, const Groups& lin, const run::LinearizeSummary& linear,
             const Load& load) {
  const std::size_t first = load.first_sample();
  print_row(name, "bus attitude", agreement(nonlinear.attitude, lin.attitude, first), "rad");
  print_row(name, "bus rate", agreement(nonlinear.rate, lin.rate, first), "/s");
  if (load.step) {
    print_row(name, "  elastic att.",
              agreement(minus_rigid(nonlinear.attitude, linear, load, true), minus_rigid(lin.attitude, linear, load, true),
                        first),
              "rad");
    print_row(name, "  elastic rate",
              agreement(minus_rigid(nonlinear.rate, linear, load, false), minus_rigid(lin.rate, linear, load, false), first),
              "/s");
  }
  print_row(name, "panel turns", agreement(nonlinear.turns, lin.turns, first), "rad");
  print_row(name, "panel modal", agreement(nonlinear.modal, lin.modal, first), "");
}

// The ringing the load's response rides on: RMS over the record of the unloaded run's panel
// turns (about their mean), in radians.
double ringing_rms(const RunRecord& rest) {
  double sum = 0.0;
  std::size_t count = 0;
  constexpr std::size_t kPanels = std::size(study::kSatellitePanels);
  Eigen::Vector3d mean[kPanels];
  for (auto& m : mean) m.setZero();
  const std::size_t n = rest.R_rel.size();
  for (std::size_t k = 0; k < n; ++k) {
    for (std::size_t p = 0; p < kPanels; ++p) mean[p] += rotation_vector(rest.R_rel[k][p] * rest.R_rel[0][p].transpose()) / n;
  }
  for (std::size_t k = 0; k < n; ++k) {
    for (std::size_t p = 0; p < kPanels; ++p) {
      sum += (rotation_vector(rest.R_rel[k][p] * rest.R_rel[0][p].transpose()) - mean[p]).squaredNorm();
      ++count;
    }
  }
  return std::sqrt(sum / static_cast<double>(count));
}

}  // namespace

int main(int argc, char** argv) {
  Load load;
  double record = 4.0;
  std::string step;
  for (int a = 1; a < argc; ++a) {
    const std::string option = argv[a];
    if (option == "load=impulse") load.step = false;
    if (option.rfind("at=", 0) == 0) load.at = std::atof(option.c_str() + 3);
    if (option.rfind("record=", 0) == 0) record = std::atof(option.c_str() + 7);
    if (option.rfind("amp=", 0) == 0) load.amplitude = std::atof(option.c_str() + 4);
    if (option.rfind("step=", 0) == 0) step = option.substr(5);
  }
  const double t_end = load.at + record;
  Load none = load;
  none.amplitude = 0.0;
  const io::Mechanism mechanism =
      study::built_mechanism(io::read_case_text(study::satellite_case_text(t_end, load.entry(t_end), step), "loaded"));
  const io::Mechanism baseline =
      study::built_mechanism(io::read_case_text(study::satellite_case_text(t_end, none.entry(t_end), step), "rest"));
  const multibody::Model& model = mechanism.model;

  // The linear models: at T as `limber linearize --at T`, at rest there, about the equilibrium.
  run::LinearizeSettings settings;
  settings.zero_threshold_hz = 0.5;
  const int bus_center = study::marker_index(model, "bus_center");
  using multibody::ChannelAxes;
  settings.inputs = {{"force", multibody::LinearInputKind::kForce, bus_center, -1, ChannelAxes::kGround},
                     {"torque", multibody::LinearInputKind::kTorque, bus_center, -1, ChannelAxes::kGround}};
  settings.outputs = {{"attitude", multibody::LinearOutputKind::kRotation, bus_center, ChannelAxes::kGround},
                      {"rate", multibody::LinearOutputKind::kAngularVelocity, bus_center, ChannelAxes::kGround}};
  const run::LinearizeSummary at_t = run::linearize_at(model, mechanism.assembly, mechanism.run, load.at, settings);
  if (!at_t.ok) {
    fmt::print(stderr, "linearization failed: {}\n", at_t.message);
    return 2;
  }
  multibody::State still = at_t.point;
  still.v.setZero();
  run::LinearizeSummary at_rest;
  const bool rest_ok = run::linearize_about(model, at_t.start.partition, still, settings, at_rest);
  run::LinearizeSettings from_statics = settings;
  from_statics.statics = true;  // `limber linearize --at T --statics`
  const run::LinearizeSummary at_equilibrium =
      run::linearize_at(model, mechanism.assembly, mechanism.run, load.at, from_statics);
  const bool equilibrium_ok = at_equilibrium.ok;
  fmt::print("statics from the state at T: {}, {} iterations, largest rigid |f| {:.2e} Hz (in motion: {:.2e} Hz)\n",
             equilibrium_ok ? "ok" : at_equilibrium.message, equilibrium_ok ? at_equilibrium.statics->iterations : 0,
             at_equilibrium.modes.largest_rigid_hz, at_t.modes.largest_rigid_hz);

  bool ok_loaded = false, ok_rest = false;
  double wall_loaded = 0.0, wall_rest = 0.0;
  const RunRecord loaded = record_run(mechanism, load.at, ok_loaded, wall_loaded);
  const RunRecord rest = record_run(baseline, load.at, ok_rest, wall_rest);
  if (!ok_loaded || !ok_rest) return 2;
  const Groups response = run_difference(loaded, rest);
  const std::size_t samples = response.attitude.front().size();

  fmt::print("deployed satellite, {} on the bus from T = {} s (x {}), {} s of record ({} samples), runs {:.0f} + {:.0f} "
             "s wall; the unloaded run's panel turns ring at {:.3e} rad RMS about their mean\n",
             load.step ? "torque step" : "20 ms impulse", load.at, load.amplitude, record, samples, wall_loaded,
             wall_rest, ringing_rms(rest));
  fmt::print("{:<12} {:<16} {:>16} {:>10} {:>9} {:>12} {:>10}\n", "linear model", "group", "linear RMS",
             "|r-l|/|l|", "gain", "after gain", "shift [ms]");
  compare("at T", response, linear_response(at_t, model, load, samples), at_t, load);
  if (rest_ok) compare("at T, v=0", response, linear_response(at_rest, model, load, samples), at_rest, load);
  if (equilibrium_ok) {
    compare("equilibrium", response, linear_response(at_equilibrium, model, load, samples), at_equilibrium, load);
  }
  fmt::print("first elastic modes at T / v=0 / equilibrium [Hz]:");
  for (Eigen::Index i = 6; i < std::min<Eigen::Index>(12, at_t.modes.frequencies_hz.size()); ++i) {
    fmt::print(" {:.4f}/{:.4f}/{:.4f}", at_t.modes.frequencies_hz(i),
               rest_ok ? at_rest.modes.frequencies_hz(i) : 0.0,
               equilibrium_ok ? at_equilibrium.modes.frequencies_hz(i) : 0.0);
  }
  fmt::print("\n");
  return 0;
}
