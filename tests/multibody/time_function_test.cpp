// Driver and actuator functions: closed-form values and derivatives, and derivatives
// against central differences.
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "core/error.h"
#include "multibody/time_function.h"

namespace limber::multibody {
namespace {

// Central differences of smooth functions with h = 1e-5: truncation ~ h² f''' ≈ 1e-10 ·
// |f'''| (≤ 1e3 here), rounding ~ 1e-16 |f| / h ≈ 1e-11: bound 1e-6.
void expect_derivatives_match(const TimeFunction& f, double x) {
  const double h = 1e-5;
  const FunctionValue v = f.evaluate(x), plus = f.evaluate(x + h), minus = f.evaluate(x - h);
  EXPECT_NEAR(v.first, (plus.value - minus.value) / (2 * h), 1e-6) << "x = " << x;
  EXPECT_NEAR(v.second, (plus.first - minus.first) / (2 * h), 1e-6) << "x = " << x;
}

TEST(TimeFunction, ConstantSpeed) {
  const FunctionValue v = TimeFunction::constant_speed(0.5, 125.0).evaluate(0.02);
  EXPECT_DOUBLE_EQ(v.value, 0.5 + 125.0 * 0.02);
  EXPECT_DOUBLE_EQ(v.first, 125.0);
  EXPECT_DOUBLE_EQ(v.second, 0.0);
}

TEST(TimeFunction, RampsReachSpeedWithHalfTheDistance) {
  // ∫₀¹ s = ½ for both shapes: f(T) = f0 + ω T / 2, then f grows at ω.
  for (RampShape shape : {RampShape::kCubic, RampShape::kQuintic}) {
    const TimeFunction f = TimeFunction::ramp(1.0, 40.0, 0.5, shape);
    EXPECT_NEAR(f.evaluate(0.5).value, 1.0 + 40.0 * 0.25, 1e-12);
    EXPECT_NEAR(f.evaluate(0.7).value, 1.0 + 40.0 * 0.25 + 40.0 * 0.2, 1e-12);
    EXPECT_NEAR(f.evaluate(0.25).first, 20.0, 1e-12);  // s(½) = ½ by symmetry
    EXPECT_DOUBLE_EQ(f.evaluate(0.0).first, 0.0);
    for (double t : {0.05, 0.17, 0.33, 0.49}) expect_derivatives_match(f, t);
  }
  // The quintic also starts and ends with zero acceleration.
  const TimeFunction q = TimeFunction::ramp(0.0, 40.0, 0.5, RampShape::kQuintic);
  EXPECT_NEAR(q.evaluate(1e-9).second, 0.0, 1e-9);
  EXPECT_NEAR(q.evaluate(0.5 - 1e-9).second, 0.0, 1e-6);
}

TEST(TimeFunction, TablesInterpolate) {
  // Linear: exact on each segment. Natural cubic spline: exact for linear data, passes
  // through the knots, and its derivatives match differences between knots.
  const TimeFunction linear = TimeFunction::table({0, 1, 3}, {0, 2, 1}, TableInterpolation::kLinear);
  EXPECT_DOUBLE_EQ(linear.evaluate(0.25).value, 0.5);
  EXPECT_DOUBLE_EQ(linear.evaluate(2.0).value, 1.5);
  EXPECT_DOUBLE_EQ(linear.evaluate(2.0).first, -0.5);
  EXPECT_DOUBLE_EQ(linear.evaluate(5.0).value, 1.0);
  const TimeFunction line = TimeFunction::table({0, 0.5, 2, 3}, {1, 2, 5, 7}, TableInterpolation::kCubic);
  EXPECT_NEAR(line.evaluate(1.3).value, 1 + 2 * 1.3, 1e-14);
  EXPECT_NEAR(line.evaluate(1.3).second, 0.0, 1e-13);
  const TimeFunction spline = TimeFunction::table({0, 1, 2, 4}, {0, 1, 0, 2}, TableInterpolation::kCubic);
  EXPECT_NEAR(spline.evaluate(2.0).value, 0.0, 1e-14);
  for (double x : {0.3, 1.5, 2.7, 3.9}) expect_derivatives_match(spline, x);
  // Continuity of the slope across a knot.
  EXPECT_NEAR(spline.evaluate(1.0 - 1e-9).first, spline.evaluate(1.0 + 1e-9).first, 1e-7);
}

TEST(TimeFunction, TableDerivativesAreRightContinuous) {
  // A motion table that starts at t = 0 with a slope must start with that slope (a zero there
  // made the initial velocities disagree with the motion and IDA fail at t = 0); at the last
  // point the end value is held, slope zero: the slope after each point, so that an integrator
  // restarting at a slope jump starts with the motion after it.
  const TimeFunction linear = TimeFunction::table({0, 1, 3}, {0, 2, 1}, TableInterpolation::kLinear);
  EXPECT_DOUBLE_EQ(linear.evaluate(0.0).first, 2.0);
  EXPECT_DOUBLE_EQ(linear.evaluate(0.0).value, 0.0);
  EXPECT_DOUBLE_EQ(linear.evaluate(1.0).first, -0.5);
  EXPECT_DOUBLE_EQ(linear.evaluate(3.0 - 1e-12).first, -0.5);
  EXPECT_DOUBLE_EQ(linear.evaluate(3.0).first, 0.0);
  EXPECT_DOUBLE_EQ(linear.evaluate(3.0).value, 1.0);
  EXPECT_DOUBLE_EQ(linear.evaluate(-1e-12).first, 0.0);
  const TimeFunction spline = TimeFunction::table({0, 1, 2, 4}, {0, 1, 0, 2}, TableInterpolation::kCubic);
  // The natural spline's start slope, from just inside; held after the end.
  EXPECT_NEAR(spline.evaluate(0.0).first, spline.evaluate(1e-9).first, 1e-7);
  EXPECT_EQ(spline.evaluate(4.0).first, 0.0);
  EXPECT_NEAR(spline.evaluate(4.0).value, 2.0, 1e-14);
}

TEST(TimeFunction, SlopeJumpsAreTheKinksOfTheMotion) {
  // Linear: every point whose two one-sided slopes differ, the ends against the held zero
  // slope; a point between two equal slopes is no jump.
  const TimeFunction linear =
      TimeFunction::table({0, 1, 2, 3, 5}, {0, 2, 4, 1, 1}, TableInterpolation::kLinear);
  EXPECT_EQ(linear.slope_jumps(), (std::vector<double>{0, 2, 3}));
  // Natural cubic spline: C² inside, so only the ends, whose slopes are not zero (checked).
  const TimeFunction spline = TimeFunction::table({0, 1, 2, 4}, {0, 1, 0, 2}, TableInterpolation::kCubic);
  EXPECT_EQ(spline.slope_jumps(), (std::vector<double>{0, 4}));
  for (const double x : {0.0, 4.0}) {
    const double inside = x == 0.0 ? 1e-7 : 4.0 - 1e-7;
    EXPECT_GT(std::abs(spline.evaluate(inside).first), 0.1);
  }
  // Smooth kinds have none.
  EXPECT_TRUE(TimeFunction::ramp(0, 1, 0.5, RampShape::kQuintic).slope_jumps().empty());
  EXPECT_TRUE(TimeFunction::constant_speed(0, 3).slope_jumps().empty());
}

TEST(TimeFunction, BadInputIsRejected) {
  EXPECT_THROW(TimeFunction::ramp(0, 1, 0.0, RampShape::kCubic), InputError);
  EXPECT_THROW(TimeFunction::table({0, 1, 1}, {0, 1, 2}, TableInterpolation::kLinear), InputError);
  EXPECT_THROW(TimeFunction::table({0}, {0}, TableInterpolation::kLinear), InputError);
}

}  // namespace
}  // namespace limber::multibody
