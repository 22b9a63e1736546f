// A torque-free spinning rigid body with a unit quaternion (nq = 7, nv = 6): exercises
// integrate_coordinates, the invariant h(q) and N(q) in both integrators.
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "integrate/simulate.h"
#include "test_systems.h"

namespace limber::integrate {
namespace {

using testing::FreeRigidBody;

struct FreeBodyErrors {
  double omega = 0.0;        // body angular velocity against the closed form [rad/s]
  double momentum = 0.0;     // |H(t) − H(0)| / |H(0)|
  double unit_norm = 0.0;    // | |p| − 1 |
  double translation = 0.0;  // centre of mass against x0 + u t [m]
};

// Axisymmetric body J = (1, 1, 2) kg m², ω(0) = (1, 0, 5) rad/s, u = (0.3, −0.2, 0.1) m/s.
// Euler's equations give ω3 = 5 and (ω1 + i ω2)(t) = e^{iΩt} with Ω = (C − A)/A ω3 = 5 rad/s.
FreeBodyErrors spin(const IntegratorOptions& options, double t_end) {
  FreeRigidBody body(2.0, Eigen::Vector3d(1.0, 1.0, 2.0));
  InitialState start;
  start.q.resize(7);
  start.q << 0.0, 0.0, 0.0, std::cos(0.2), std::sin(0.2), 0.0, 0.0;  // tilted 0.4 rad about x
  start.v.resize(6);
  start.v << 0.3, -0.2, 0.1, 1.0, 0.0, 5.0;
  const double big_omega = 5.0;
  const Eigen::Vector3d h0 = body.angular_momentum(start.q, start.v);
  FreeBodyErrors e;
  const auto result = simulate(body, options, start, uniform_sample_times(0.0, t_end, 0.1),
                               [&](const Sample& s) {
    const Eigen::Vector3d omega(std::cos(big_omega * s.t), std::sin(big_omega * s.t), 5.0);
    e.omega = std::max(e.omega, (s.v.tail<3>() - omega).lpNorm<Eigen::Infinity>());
    e.momentum = std::max(e.momentum, (body.angular_momentum(s.q, s.v) - h0).norm() / h0.norm());
    e.unit_norm = std::max(e.unit_norm, std::abs(s.q.segment<4>(3).norm() - 1.0));
    e.translation = std::max(e.translation,
                             (s.q.head<3>() - start.v.head<3>() * s.t).lpNorm<Eigen::Infinity>());
  });
  EXPECT_TRUE(result.status.ok()) << result.status.message;
  std::printf("%s: omega %.3e, momentum %.3e, unit %.3e, translation %.3e, steps %ld\n",
              to_string(options.method), e.omega, e.momentum, e.unit_norm, e.translation,
              result.statistics.steps);
  return e;
}

TEST(FreeBody, GeneralizedAlphaIsSecondOrderOnTheLieGroup) {
  // h = 2, 1, 0.5 ms over 2 s (10 rad of spin, Ωh ≤ 0.01): the slope of the ω error is 2 ± 0.15
  // (asymptotic range as for the oscillator). The exponential update keeps |p| = 1 to round-off
  // (at most ~n ε = 4.4e-13 after n = 4000 quaternion products, while an update off the group
  // drifts by O(h²) ~ 1e-6); H is conserved to the
  // method's O(h²) error: bound 2 × the measured ω error relative to |ω|.
  const std::vector<double> steps{2e-3, 1e-3, 5e-4};
  std::vector<FreeBodyErrors> errors;
  for (const double h : steps) errors.push_back(spin(IntegratorOptions::generalized_alpha(h, 0.8), 2.0));
  const double order = std::log(errors[0].omega / errors[2].omega) / std::log(4.0);
  EXPECT_NEAR(order, 2.0, 0.15);
  for (const auto& e : errors) {
    EXPECT_LT(e.unit_norm, 1e-12);
    EXPECT_LT(e.momentum, 2.0 * e.omega / 5.0);
    // Translation is linear in t, integrated exactly up to round-off.
    EXPECT_LT(e.translation, 1e-12);
  }
}

TEST(FreeBody, IdaConservesMomentumAndTheQuaternionNorm) {
  // rtol = atol = 1e-9: ω and H within 100 tol (global error of ~10 rad of rotation), |p| − 1
  // within 10 tol (the GGL invariant h = 0 is an algebraic equation solved to IDA's Newton
  // tolerance, a fraction of the local error bound).
  const double tol = 1e-9;
  const FreeBodyErrors e = spin(IntegratorOptions::ida(tol, tol), 2.0);
  EXPECT_LT(e.omega, 100.0 * tol * 5.0);
  EXPECT_LT(e.momentum, 100.0 * tol);
  EXPECT_LT(e.unit_norm, 10.0 * tol);
  EXPECT_LT(e.translation, 100.0 * tol);
}

// Heavy top: m = 2 kg, J = (0.02, 0.02, 0.01) kg m², joint 0.1 m above the centre of mass,
// tilted 0.3 rad, spinning at 50 rad/s about its axis; 2 s. Returns the largest energy and
// vertical-momentum deviations [J, kg m²/s] and constraint residual |g| [m]; prints all.
struct TopErrors {
  double energy = 0.0, momentum = 0.0, constraint = 0.0, unit_norm = 0.0;
};

TopErrors spin_top(const IntegratorOptions& options) {
  using testing::HeavyTop;
  HeavyTop top(2.0, Eigen::Vector3d(0.02, 0.02, 0.01), Eigen::Vector3d(0.0, 0.0, -0.1), 9.81);
  InitialState start;
  start.q.resize(7);
  start.q << 0.0, 0.0, 0.0, std::cos(0.15), std::sin(0.15), 0.0, 0.0;
  start.v = Eigen::VectorXd::Zero(6);
  start.v(5) = 50.0;
  TopErrors e;
  double e0 = 0.0, l0 = 0.0;
  bool first = true;
  Eigen::VectorXd g;
  const auto result = simulate(top, options, start, uniform_sample_times(0.0, 2.0, 0.01),
                               [&](const Sample& s) {
    if (first) e0 = top.energy(s.q, s.v), l0 = top.vertical_momentum(s.q, s.v), first = false;
    e.energy = std::max(e.energy, std::abs(top.energy(s.q, s.v) - e0));
    e.momentum = std::max(e.momentum, std::abs(top.vertical_momentum(s.q, s.v) - l0));
    top.constraints(s.t, s.q, g);
    e.constraint = std::max(e.constraint, g.norm());
    e.unit_norm = std::max(e.unit_norm, std::abs(s.q.segment<4>(3).norm() - 1.0));
  });
  EXPECT_TRUE(result.status.ok()) << result.status.message;
  std::printf("%s: energy %.3e J, L_z %.3e, |g| %.3e, |p| - 1 %.3e, steps %ld\n",
              to_string(options.method), e.energy, e.momentum, e.constraint, e.unit_norm,
              result.statistics.steps);
  return e;
}

TEST(HeavyTop, IdaKeepsEnergyMomentumConstraintsAndUnitQuaternion) {
  // Constraints and a quaternion together through the GGL form. rtol = atol = 1e-8; energy
  // (14.4 J) and L_z (0.48 kg m²/s) within 100 tol relative (as for the pendulum); |g| and
  // |p| − 1 within 10 tol (algebraic equations solved to IDA's Newton tolerance).
  const double tol = 1e-8;
  const TopErrors e = spin_top(IntegratorOptions::ida(tol, tol));
  EXPECT_LT(e.energy, 100.0 * tol * 14.4);
  EXPECT_LT(e.momentum, 100.0 * tol * 0.48);
  EXPECT_LT(e.constraint, 10.0 * tol);
  EXPECT_LT(e.unit_norm, 10.0 * tol);
}

TEST(HeavyTop, GeneralizedAlphaConvergesAtSecondOrderWithExactInvariants) {
  // h = 1 ms and 0.25 ms: energy and L_z errors must fall 16-fold (order 2; accepted 12–20,
  // i.e. order 1.8–2.2). g = 0 holds to the Newton tolerance: corrections stop below
  // 1e-8 ‖ξ‖, ‖ξ‖ ≈ 50 rad/s × 1 ms = 0.05, so |g| < 5e-10 m; |p| = 1 to round-off
  // (random walk √n ε ≈ 2e-14 over n = 8000 quaternion products; bound 1e-12).
  const TopErrors coarse = spin_top(IntegratorOptions::generalized_alpha(1e-3, 0.8));
  const TopErrors fine = spin_top(IntegratorOptions::generalized_alpha(2.5e-4, 0.8));
  EXPECT_GT(coarse.energy / fine.energy, 12.0);
  EXPECT_LT(coarse.energy / fine.energy, 20.0);
  EXPECT_GT(coarse.momentum / fine.momentum, 12.0);
  EXPECT_LT(coarse.momentum / fine.momentum, 20.0);
  for (const TopErrors& e : {coarse, fine}) {
    EXPECT_LT(e.constraint, 5e-10);
    EXPECT_LT(e.unit_norm, 1e-12);
  }
}

}  // namespace
}  // namespace limber::integrate
