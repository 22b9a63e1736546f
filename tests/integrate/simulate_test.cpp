// The run driver: output sampling independent of the steps, interpolation accuracy, failure
// statuses (when and why, samples before kept) and input errors.
#include "integrate/simulate.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include <gtest/gtest.h>

#include "core/error.h"
#include "test_systems.h"

namespace limber::integrate {
namespace {

using testing::CartesianPendulum;
using testing::ForwardingSystem;

constexpr double kMass = 1.0, kLength = 1.0, kGravity = 9.81, kTheta0 = 1.0;

InitialState pendulum_start(const CartesianPendulum& pendulum) {
  return {0.0, pendulum.position(kTheta0), Eigen::VectorXd::Zero(2)};
}

TEST(UniformSampleTimes, EndExactlyAtTheEndTime) {
  EXPECT_EQ(uniform_sample_times(0.0, 1.0, 0.25), (std::vector<double>{0, 0.25, 0.5, 0.75, 1.0}));
  // i dt up to round-off, then the end time itself.
  const auto thirds = uniform_sample_times(0.0, 1.0, 0.3);
  ASSERT_EQ(thirds.size(), 5u);
  for (int i = 0; i < 4; ++i) EXPECT_DOUBLE_EQ(thirds[i], 0.3 * i);
  EXPECT_EQ(thirds.back(), 1.0);
  // 0.1 does not divide 1 in binary: still 11 samples ending at 1.
  const auto tenths = uniform_sample_times(0.0, 1.0, 0.1);
  ASSERT_EQ(tenths.size(), 11u);
  EXPECT_EQ(tenths.back(), 1.0);
  EXPECT_THROW(uniform_sample_times(0.0, 1.0, 0.0), InputError);
  EXPECT_THROW(uniform_sample_times(1.0, 0.0, 0.1), InputError);
  // Spans whose sample count would overflow or exhaust memory (a crash before).
  EXPECT_THROW(uniform_sample_times(0.0, 1e308, 0.1), InputError);
  EXPECT_THROW(uniform_sample_times(0.0, std::numeric_limits<double>::infinity(), 0.1), InputError);
  EXPECT_THROW(uniform_sample_times(0.0, 1.0, 1e-300), InputError);
  EXPECT_THROW(uniform_sample_times(0.0, 1e9, 1.0), InputError);
}

TEST(UniformSampleTimes, GeneratedOnDemandWithoutHoldingThem) {
  // The largest grid allowed (1e8 + 1 times, 800 MB as a list) costs nothing until asked, and
  // gives the same times as the list form.
  const SampleTimes huge = SampleTimes::uniform(0.0, 1e7, 0.1);
  EXPECT_EQ(huge.size(), 100000001u);
  EXPECT_DOUBLE_EQ(huge[12345], 1234.5);
  EXPECT_EQ(huge.back(), 1e7);
  for (const double dt : {0.25, 0.3, 0.1, 0.0137}) {
    const SampleTimes grid = SampleTimes::uniform(0.0, 1.0, dt);
    const std::vector<double> list = uniform_sample_times(0.0, 1.0, dt);
    ASSERT_EQ(grid.size(), list.size());
    for (std::size_t i = 0; i < list.size(); ++i) EXPECT_EQ(grid[i], list[i]);
  }
  EXPECT_THROW(SampleTimes({0.0, 0.5, 0.5}), InputError);
  EXPECT_THROW(SampleTimes(std::vector<double>{}), InputError);
}

TEST(Simulate, SamplesDoNotChangeTheSteps) {
  // Output times are interpolated, never forced step ends (PITFALLS): 1001 samples cost the
  // same steps as 11. Generalized-α: exactly t/h steps. IDA: the same step sequence, so the
  // common samples agree to round-off.
  CartesianPendulum pendulum(kMass, kLength, kGravity);
  const auto sparse = uniform_sample_times(0.0, 1.0, 0.1);
  const auto dense = uniform_sample_times(0.0, 1.0, 0.001);
  for (const auto& options :
       {IntegratorOptions::generalized_alpha(0.01, 0.8), IntegratorOptions::ida(1e-6, 1e-6)}) {
    std::vector<Sample> few, many;
    const auto a = simulate(pendulum, options, pendulum_start(pendulum), sparse,
                            [&](const Sample& s) { few.push_back(s); });
    const auto b = simulate(pendulum, options, pendulum_start(pendulum), dense,
                            [&](const Sample& s) { many.push_back(s); });
    ASSERT_TRUE(a.status.ok() && b.status.ok());
    EXPECT_EQ(a.samples, 11);
    EXPECT_EQ(b.samples, 1001);
    EXPECT_EQ(a.statistics.steps, b.statistics.steps) << to_string(options.method);
    if (options.method == Method::kGeneralizedAlpha) {
      EXPECT_EQ(a.statistics.steps, 100);
    }
    EXPECT_LT(a.statistics.steps, 1001);
    EXPECT_NEAR(few.back().q(0), many.back().q(0), 1e-12);
  }
}

TEST(Simulate, OnStepSeesTheStartAndEveryStepEndInOrder) {
  // Both integrators: one call at the start, then one per accepted step (no events, so no step
  // shorter than generalized-α's 1 % that on_step leaves out), in
  // ascending time, the last at the end time with the state the last sample delivers; every
  // state satisfies the dynamics M v̇ + Gᵀλ = Q (the pendulum's, evaluated here) to the
  // integrators' Newton tolerance.
  CartesianPendulum pendulum(kMass, kLength, kGravity);
  for (IntegratorOptions options :
       {IntegratorOptions::generalized_alpha(0.01, 0.8), IntegratorOptions::ida(1e-6, 1e-6)}) {
    std::vector<double> times;
    double worst_residual = 0.0;
    Eigen::VectorXd last_q;
    options.on_step = [&](double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v, const Eigen::VectorXd& vdot,
                          const Eigen::VectorXd& lambda) {
      times.push_back(t);
      last_q = q;
      Eigen::MatrixXd M, G;
      Eigen::VectorXd Q;
      pendulum.mass_matrix(t, q, M);
      pendulum.generalized_forces(t, q, v, Q);
      pendulum.constraint_jacobian_v(t, q, G);
      worst_residual = std::max(worst_residual, (M * vdot + G.transpose() * lambda - Q).lpNorm<Eigen::Infinity>());
    };
    Sample last;
    const auto result = simulate(pendulum, options, pendulum_start(pendulum), uniform_sample_times(0.0, 1.0, 0.1),
                                 [&](const Sample& s) { last = s; });
    ASSERT_TRUE(result.status.ok());
    ASSERT_EQ(static_cast<long>(times.size()), result.statistics.steps + 1) << to_string(options.method);
    EXPECT_EQ(times.front(), 0.0);
    EXPECT_TRUE(std::is_sorted(times.begin(), times.end()));
    EXPECT_NEAR(times.back(), 1.0, 1e-12);
    EXPECT_LT((last_q - last.q).lpNorm<Eigen::Infinity>(), 1e-12) << to_string(options.method);
    // |Q| ~ m g = 9.81 N. Gen-α solves the step's dynamics by Newton to 1e-8 relative: 1e-6 N.
    // IDA stops Newton at a third of its weighted tolerance on the increments, so the residual
    // left is about c_j M Δv, c_j ~ 1/h ~ 1e2..1e3 1/s and Δv ~ rtol |v| ~ 3e-6 m/s: up to
    // 3e-3 N (measured 7.7e-4 N).
    const bool ida = options.method == Method::kIda;
    EXPECT_LT(worst_residual, ida ? 3e-3 : 1e-6) << to_string(options.method) << ": " << worst_residual;
  }
}

TEST(Simulate, GeneralizedAlphaInterpolationIsSecondOrder) {
  // Samples every 13.7 ms fall inside steps of 4, 2, 1 ms: the interpolated q and v must keep
  // the scheme's order 2 (cubic Hermite for q, linear for v: both O(h²)); band ±0.15 as in the
  // order tests.
  CartesianPendulum pendulum(kMass, kLength, kGravity);
  const auto times = uniform_sample_times(0.0, 1.0, 0.0137);
  const auto reference = pendulum.reference(kTheta0, 0.0, times);
  std::vector<double> q_errors, v_errors;
  for (const double h : {4e-3, 2e-3, 1e-3}) {
    double q_error = 0, v_error = 0;
    int i = 0;
    simulate(pendulum, IntegratorOptions::generalized_alpha(h, 0.8), pendulum_start(pendulum),
             times, [&](const Sample& s) {
               const Eigen::Vector2d& ref = reference[i++];
               q_error = std::max(q_error, (s.q - pendulum.position(ref(0))).lpNorm<Eigen::Infinity>());
               v_error = std::max(
                   v_error, (s.v - pendulum.velocity(ref(0), ref(1))).lpNorm<Eigen::Infinity>());
             });
    q_errors.push_back(q_error);
    v_errors.push_back(v_error);
  }
  EXPECT_NEAR(std::log(q_errors[0] / q_errors[2]) / std::log(4.0), 2.0, 0.15);
  EXPECT_NEAR(std::log(v_errors[0] / v_errors[2]) / std::log(4.0), 2.0, 0.15);
}

// A pendulum whose forces turn NaN after t_break.
class BrokenPendulum final : public ForwardingSystem {
 public:
  BrokenPendulum(MechanicalSystem& base, double t_break)
      : ForwardingSystem(base), t_break_(t_break) {}
  void generalized_forces(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                          Eigen::VectorXd& Q) override {
    base_.generalized_forces(t, q, v, Q);
    if (t > t_break_) Q(0) = std::numeric_limits<double>::quiet_NaN();
  }

 private:
  double t_break_;
};

// A pendulum whose single constraint is stated twice (dependent rows).
class DoubledConstraint final : public ForwardingSystem {
 public:
  using ForwardingSystem::ForwardingSystem;
  int nc() const override { return 2; }
  void constraints(double t, const Eigen::VectorXd& q, Eigen::VectorXd& g) override {
    base_.constraints(t, q, g);
    g = Eigen::Vector2d(g(0), g(0));
  }
  void constraint_jacobian_q(double t, const Eigen::VectorXd& q,
                             Eigen::MatrixXd& g_q) override {
    base_.constraint_jacobian_q(t, q, g_q);
    g_q = Eigen::MatrixXd(g_q.replicate(2, 1));
  }
  void constraint_jacobian_v(double t, const Eigen::VectorXd& q,
                             Eigen::MatrixXd& G) override {
    base_.constraint_jacobian_v(t, q, G);
    G = Eigen::MatrixXd(G.replicate(2, 1));
  }
  void constraint_time_derivative(double, const Eigen::VectorXd&,
                                  Eigen::VectorXd& g_t) override {
    g_t = Eigen::VectorXd::Zero(2);
  }
  void acceleration_rhs(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                        Eigen::VectorXd& gamma) override {
    base_.acceleration_rhs(t, q, v, gamma);
    gamma = Eigen::Vector2d(gamma(0), gamma(0));
  }
};

TEST(Simulate, NonFiniteForcesEndTheRunWithNaNAfterTheLastGoodSample) {
  // Forces turn NaN after 0.33 s: samples 0, 0.1, 0.2, 0.3 are delivered, then kNaN at a time
  // within one step (gen-α: 10 ms) or one IDA step of 0.33 s, with the time in the message.
  CartesianPendulum pendulum(kMass, kLength, kGravity);
  BrokenPendulum broken(pendulum, 0.33);
  for (const auto& options :
       {IntegratorOptions::generalized_alpha(0.01, 0.8), IntegratorOptions::ida(1e-6, 1e-6)}) {
    int samples = 0;
    const auto result = simulate(broken, options, pendulum_start(pendulum),
                                 uniform_sample_times(0.0, 1.0, 0.1),
                                 [&](const Sample&) { ++samples; });
    EXPECT_EQ(result.status.code, StatusCode::kNaN)
        << to_string(options.method) << ": " << result.status.message;
    EXPECT_EQ(samples, 4);
    EXPECT_EQ(result.samples, 4);
    EXPECT_GT(result.status.t, 0.3);
    EXPECT_LT(result.status.t, 0.4);
    EXPECT_NE(result.status.message.find("at t = 0.3"), std::string::npos)
        << result.status.message;
  }
}

TEST(Simulate, DependentConstraintsAreASingularJacobian) {
  CartesianPendulum pendulum(kMass, kLength, kGravity);
  DoubledConstraint doubled(pendulum);
  for (const auto& options :
       {IntegratorOptions::generalized_alpha(0.01, 0.8), IntegratorOptions::ida(1e-6, 1e-6)}) {
    const auto result = simulate(doubled, options, pendulum_start(pendulum), {0.0, 1.0},
                                 [](const Sample&) {});
    EXPECT_EQ(result.status.code, StatusCode::kSingularJacobian) << result.status.message;
    EXPECT_EQ(result.samples, 0);
    EXPECT_EQ(result.status.t, 0.0);
  }
}

// A pendulum whose constraint has no solution after t_break: x² + y² = −L².
class ImpossibleConstraint final : public ForwardingSystem {
 public:
  ImpossibleConstraint(MechanicalSystem& base, double length, double t_break)
      : ForwardingSystem(base), length_(length), t_break_(t_break) {}
  void constraints(double t, const Eigen::VectorXd& q, Eigen::VectorXd& g) override {
    base_.constraints(t, q, g);
    if (t > t_break_) g(0) += length_ * length_;
  }

 private:
  double length_, t_break_;
};

TEST(Simulate, NewtonFailureIsNeverAcceptedAndReportsConvergenceFailure) {
  // After 0.255 s no configuration satisfies the constraint: Newton cannot converge, the step
  // is rejected and halved 6 times (7 rejections at least), then the run stops near 0.255 s
  // with kConvergenceFailures instead of accepting an unconverged step; samples 0, 0.1, 0.2
  // were delivered.
  CartesianPendulum pendulum(kMass, kLength, kGravity);
  ImpossibleConstraint impossible(pendulum, kLength, 0.255);
  const auto result = simulate(impossible, IntegratorOptions::generalized_alpha(0.01, 0.8),
                               pendulum_start(pendulum), {0.0, 0.1, 0.2, 0.3},
                               [](const Sample&) {});
  EXPECT_EQ(result.status.code, StatusCode::kConvergenceFailures) << result.status.message;
  EXPECT_EQ(result.samples, 3);
  EXPECT_GE(result.statistics.rejected_steps, 7);
  EXPECT_GE(result.status.t, 0.25);
  EXPECT_LT(result.status.t, 0.26);
  EXPECT_NE(result.status.message.find("Newton did not converge"), std::string::npos)
      << result.status.message;
}

TEST(Simulate, StepBudgetEndsTheRun) {
  CartesianPendulum pendulum(kMass, kLength, kGravity);
  for (auto options :
       {IntegratorOptions::generalized_alpha(0.01, 0.8), IntegratorOptions::ida(1e-6, 1e-6)}) {
    options.max_steps = 10;
    const auto result = simulate(pendulum, options, pendulum_start(pendulum), {0.0, 1.0},
                                 [](const Sample&) {});
    EXPECT_EQ(result.status.code, StatusCode::kTooManySteps) << result.status.message;
    EXPECT_EQ(result.samples, 1);
  }
}

// The InputError message of `call`, or "" when it does not throw.
template <typename Call>
std::string input_error(Call call) {
  try {
    call();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(Simulate, BadInputThrowsWithExpectedAndGot) {
  CartesianPendulum pendulum(kMass, kLength, kGravity);
  const auto ignore = [](const Sample&) {};
  const auto ida = IntegratorOptions::ida(1e-6, 1e-6);
  EXPECT_NE(input_error([&] { simulate(pendulum, ida, pendulum_start(pendulum), {0.0, 0.5, 0.5}, ignore); })
                .find("expected > 0.5"),
            std::string::npos);
  EXPECT_NE(input_error([&] { simulate(pendulum, ida, pendulum_start(pendulum), {-1.0, 0.5}, ignore); })
                .find("expected ≥ 0"),
            std::string::npos);
  EXPECT_NE(input_error([&] {
              simulate(pendulum, IntegratorOptions::generalized_alpha(0.01, 1.5),
                       pendulum_start(pendulum), {0.0, 1.0}, ignore);
            }).find("rho_inf: expected 0 ≤ rho_inf ≤ 1, got 1.5"),
            std::string::npos);
  EXPECT_NE(input_error([&] {
              simulate(pendulum, IntegratorOptions::ida(0.0, 1e-6), pendulum_start(pendulum),
                       {0.0, 1.0}, ignore);
            }).find("rtol: expected"),
            std::string::npos);
  const InitialState wrong_size{0.0, Eigen::VectorXd::Zero(3), Eigen::VectorXd::Zero(2)};
  EXPECT_NE(input_error([&] { simulate(pendulum, ida, wrong_size, {0.0, 1.0}, ignore); })
                .find("expected 2 coordinates and 2 velocities, got 3 and 2"),
            std::string::npos);
}

}  // namespace
}  // namespace limber::integrate
