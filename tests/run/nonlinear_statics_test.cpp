// Statics with a nonlinear body (multibody/statics.h: the beams' tangent, loads stepped on) and
// force elements and acceleration probes on its nodes, through the case reader and the run
// layer: the 1 m steel beam of nonlinear_beam_case.h (10 x 20 mm, 20 elements) bracketed to
// ground at node 1, bending about its weak axis (EI = E w³h/12 = 344.67 N m², deflection along
// ground y), against closed forms: the sag under its own weight and a tip spring (TSDA, RSDA)
// beside the beam's stiffness. (The elastica of a large tip load is not reached yet:
// docs/nonlinear-beams.md, "Statics with a nonlinear body".)
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "io/case_reader.h"
#include "io/case_reduction.h"
#include "io/mechanism_builder.h"
#include "multibody/acceleration_probe.h"
#include "nonlinear_beam_case.h"
#include "run/run_driver.h"
#include "run/statics_run.h"

namespace limber::run {
namespace {

constexpr double kLength = 1.0;                                       // [m]
constexpr double kEI = 206.8e9 * 0.02 * 0.01 * 0.01 * 0.01 / 12.0;    // weak axis [N m²]
constexpr double kWeight = 7820.0 * 0.01 * 0.02 * 9.81;               // per length [N/m]

io::Mechanism build(const std::string& text) {
  const io::Case input = io::read_case_text(text, "nonlinear_statics.yaml");
  return io::build_mechanism(input, io::reduce_case(input, io::ReductionScope::kMechanismBodies));
}

// The cantilever with `gravity`, a marker `tip` at node 21 and `rest` (forces, probes, run).
std::string cantilever(const std::string& gravity, const std::string& rest) {
  return test::nonlinear_beam_case("0", "", "gravity: " + gravity + "\n" +
                                   "markers:\n  tip: {body: beam, node: tip}\n"
                                   "joints:\n  clamp: {type: bracket, body_i: ground, body_j: beam, position: [0, 0, 0]}\n" +
                                   rest);
}

// The tip node's ground position and z rotation (its x axis turned in the x-y plane) at q.
struct Tip {
  Eigen::Vector3d r;
  double angle = 0.0;
};
Tip tip_of(const multibody::Model& model, const Eigen::VectorXd& q) {
  const int b = model.find_body("beam.node21");
  EXPECT_GE(b, 0);
  const int o = model.bodies[static_cast<std::size_t>(b)].q_offset;
  const Eigen::Quaterniond p(q(o + 3), q(o + 4), q(o + 5), q(o + 6));
  const Eigen::Vector3d x = p.toRotationMatrix().col(0);
  return {q.segment<3>(o), std::atan2(x.y(), x.x())};
}

// Solves the statics of `text`; expects success.
Tip static_tip(const std::string& text) {
  const io::Mechanism built = build(text);
  const StaticsSummary summary = solve_mechanism_statics(built.model, built.assembly);
  EXPECT_TRUE(summary.ok) << summary.message;
  return tip_of(built.model, summary.statics.state.q);
}

std::string tip_load(double force_y) {
  return "forces:\n  push: {type: point_load, marker: tip, force: [0, " + std::to_string(force_y) + ", 0]}\n";
}

// Its own weight q along −y: tip sag qL⁴/(8EI) = 5.565 mm and tip rotation qL³/(6EI). The
// lumped node weights leave out the consistent load's end moment ql²/12 at the tip, which
// changes the sag by (l/L)²/3 = 0.08 % and the rotation by (l/L)²/2 = 0.13 % (l = L/20); the
// large-rotation terms are O((sag/L)²) ≈ 3e-5. 0.3 % holds both with room.
TEST(NonlinearStatics, SagUnderItsOwnWeightMatchesTheLinearCantilever) {
  const Tip tip = static_tip(cantilever("[0, -9.81, 0]", ""));
  const double sag = kWeight * std::pow(kLength, 4) / (8 * kEI);
  const double rotation = kWeight * std::pow(kLength, 3) / (6 * kEI);
  std::printf("sag %.6f m (EI closed form %.6f), tip rotation %.6f rad (%.6f)\n", -tip.r.y(), sag, -tip.angle, rotation);
  EXPECT_NEAR(-tip.r.y() / sag, 1.0, 3e-3);
  EXPECT_NEAR(-tip.angle / rotation, 1.0, 3e-3);
}

// A tip spring beside the cantilever under a small tip load P (v/L ≈ 1e-3: the elastica's
// correction is O(α²) ≈ 1e-5). A TSDA of stiffness k along y from a ground point below the tip:
// v = P / (3EI/L³ + k). An RSDA about z between ground and the tip node, k_r = EI/L: the tip
// rotation θ = (PL²/2EI) / (1 + k_r L/EI), v = PL³/3EI − k_r θ L²/2EI. Both are the Euler–
// Bernoulli cantilever's, which the mesh reproduces at the nodes under nodal loads, so 1e-4
// holds the O(α²) terms and the Newton tolerance.
TEST(NonlinearStatics, TipSpringsOnANodeAddTheirStiffness) {
  const double P = 0.5, k = 3 * kEI / std::pow(kLength, 3);
  const std::string tsda = "markers:\n  below: {body: ground, position: [1, -0.5, 0]}\n";
  std::string text = cantilever("[0, 0, 0]", tip_load(-P) +
                                                 "  spring: {type: tsda, marker_i: below, marker_j: tip, "
                                                 "stiffness: " + std::to_string(k) + ", free_length: 0.5}\n");
  text.replace(text.find("markers:\n"), 9, tsda);
  const double v_tsda = P / (3 * kEI / std::pow(kLength, 3) + k);
  const Tip with_tsda = static_tip(text);
  std::printf("TSDA: v %.8f m (closed form %.8f)\n", -with_tsda.r.y(), v_tsda);
  EXPECT_NEAR(-with_tsda.r.y() / v_tsda, 1.0, 1e-4);

  const double k_r = kEI / kLength;
  text = cantilever("[0, 0, 0]", tip_load(-P) +
                                     "  hinge: {type: rsda, marker_i: fixed, marker_j: tip, stiffness: " +
                                     std::to_string(k_r) + "}\n");
  text.replace(text.find("markers:\n"), 9, "markers:\n  fixed: {body: ground, position: [1, 0, 0]}\n");
  const double theta = (P * kLength * kLength / (2 * kEI)) / (1 + k_r * kLength / kEI);
  const double v_rsda = P * std::pow(kLength, 3) / (3 * kEI) - k_r * theta * kLength * kLength / (2 * kEI);
  const Tip with_rsda = static_tip(text);
  std::printf("RSDA: v %.8f m (closed form %.8f), rotation %.8f rad (%.8f)\n", -with_rsda.r.y(), v_rsda,
              -with_rsda.angle, theta);
  EXPECT_NEAR(-with_rsda.r.y() / v_rsda, 1.0, 1e-4);
  EXPECT_NEAR(-with_rsda.angle / theta, 1.0, 1e-4);
}

// `run: {start: statics}`: the run starts from the sagged equilibrium and stays there (from the
// straight beam the tip would swing through twice the sag). The equilibrium holds the forces
// to 1e-9 of the largest; the generalized-α keeps a state at rest at rest to its Newton
// tolerance: 1e-6 of the sag is far above both and far below a swing.
TEST(NonlinearStatics, StaticStartStaysAtRest) {
  const io::Mechanism built = build(cantilever(
      "[0, -9.81, 0]", "run: {integrator: galpha, step: 2.0e-4, t_end: 0.02, sample_interval: 2.0e-3, start: statics}\n"));
  const double sag = kWeight * std::pow(kLength, 4) / (8 * kEI);
  std::vector<double> tip_y;
  RunHooks hooks;
  hooks.on_sample = [&](const integrate::Sample& sample, const results::Sample&) {
    tip_y.push_back(tip_of(built.model, sample.q).r.y());
  };
  const RunSummary summary = run_mechanism(built.model, built.assembly, built.run, hooks);
  ASSERT_TRUE(summary.ok) << summary.message;
  ASSERT_GE(tip_y.size(), 2u);
  EXPECT_NEAR(-tip_y.front() / sag, 1.0, 3e-3);  // the sag above
  double drift = 0.0;
  for (const double y : tip_y) drift = std::max(drift, std::abs(y - tip_y.front()));
  std::printf("static start: tip sag %.6f m, largest move over the run %.3g m\n", -tip_y.front(), drift);
  EXPECT_LT(drift, 1e-6 * sag);
}

// An acceleration probe at the tip node of the beam swinging as a pendulum (hinged at node 1
// about z, released horizontal under gravity along −y): the recorded acceleration against
// central differences of the node's velocity (a second method), as for a modal body's node
// (acceleration_probe_run_test.cpp). The difference errs by h²/6 |a'''| and the generalized-α's
// velocity update by O(h ω) on the bending modes the release rings (36 Hz and up): 1.2 % of the
// peak at h = 5e-5 s, so h = 2e-5 s for 1 %.
TEST(NonlinearStatics, ProbeOnANodeMatchesDifferencesOfItsVelocity) {
  std::string text = cantilever("[0, -9.81, 0]", "acceleration_probes:\n  tip_probe: {body: beam, node: tip}\n"
                                                 "  tip_marker: {marker: tip}\n"
                                                 "run: {integrator: galpha, step: 2.0e-5, t_end: 0.05, "
                                                 "sample_interval: 2.0e-5}\n");
  text.replace(text.find("type: bracket"), 13, "type: revolute");
  const io::Mechanism built = build(text);
  const multibody::Model& model = built.model;
  ASSERT_EQ(model.acceleration_probes.size(), 2u);
  std::vector<double> t;
  std::vector<Eigen::Vector3d> velocity, probe, marker_probe;
  multibody::FrameKinematics frame;
  RunHooks hooks;
  hooks.on_sample = [&](const integrate::Sample& sample, const results::Sample& record) {
    t.push_back(sample.t);
    velocity.push_back(multibody::probe_motion(model, model.acceleration_probes[0], sample.q, sample.v, sample.vdot,
                                               frame).v_W);
    probe.push_back(record.probe_accelerations.at(0));
    marker_probe.push_back(record.probe_accelerations.at(1));
  };
  const RunSummary summary = run_mechanism(model, built.assembly, built.run, hooks);
  ASSERT_TRUE(summary.ok) << summary.message;
  double peak = 0.0, error = 0.0, between = 0.0;
  for (std::size_t k = 1; k + 1 < t.size(); ++k) {
    const Eigen::Vector3d difference = (velocity[k + 1] - velocity[k - 1]) / (t[k + 1] - t[k - 1]);
    error = std::max(error, (difference - probe[k]).norm());
    peak = std::max(peak, probe[k].norm());
    between = std::max(between, (probe[k] - marker_probe[k]).norm());
  }
  std::printf("tip probe: peak %.4g m/s^2, largest difference from d(v)/dt %.3g of it\n", peak, error / peak);
  EXPECT_GT(peak, 9.81);  // the tip falls and swings: at least g at the release
  EXPECT_LT(error, 0.01 * peak);
  EXPECT_EQ(between, 0.0);  // at the node or at its marker: the same point
}

}  // namespace
}  // namespace limber::run
