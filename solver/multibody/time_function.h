// Scalar functions of one variable (time t [s], or an angle for RSDA actuators) with
// exact first and second derivatives, used by drivers and force elements.
//   constant:        f = c
//   constant speed:  f = f0 + ω t
//   ramp:            spin-up from rest to speed ω over [0, T]: ḟ = ω s(t/T) with
//                    s(τ) = 3τ² − 2τ³ (cubic) or 10τ³ − 15τ⁴ + 6τ⁵ (quintic, also
//                    zero acceleration at both ends), then ḟ = ω; f(0) = f0.
//   table:           points (x_k, y_k), linear or natural cubic spline interpolation,
//                    held constant (zero slope) outside [x_0, x_n]. The derivatives are
//                    right-continuous: at x_0 (and at a linear table's interior points) those
//                    of the segment after it, at x_n zero (held after it).
#pragma once

#include <vector>

namespace limber::multibody {

enum class RampShape { kCubic, kQuintic };
enum class TableInterpolation { kLinear, kCubic };

struct FunctionValue {
  double value = 0.0;
  double first = 0.0;   // d/dx
  double second = 0.0;  // d²/dx²
};

class TimeFunction {
 public:
  // f = 0.
  TimeFunction() = default;
  static TimeFunction constant(double value);
  static TimeFunction constant_speed(double initial, double speed);
  // Throws InputError when duration ≤ 0.
  static TimeFunction ramp(double initial, double speed, double duration, RampShape shape);
  // Throws InputError for fewer than 2 points, non-increasing x, or mismatched sizes.
  static TimeFunction table(std::vector<double> x, std::vector<double> y,
                            TableInterpolation interpolation);

  FunctionValue evaluate(double x) const;

  // Where the first derivative jumps (ascending): a linear table's interior points whose
  // slopes differ, and x_0 and x_n of a table whose end slopes are not zero (held outside).
  // A prescribed motion's velocity jumps there: the integrators stop and restart there
  // (MechanicalSystem::velocity_breakpoints). Empty for the smooth kinds.
  std::vector<double> slope_jumps() const;

 private:
  enum class Kind { kConstant, kConstantSpeed, kRamp, kTable };
  Kind kind_ = Kind::kConstant;
  double initial_ = 0.0;
  double speed_ = 0.0;
  double duration_ = 1.0;
  RampShape shape_ = RampShape::kQuintic;
  TableInterpolation interpolation_ = TableInterpolation::kLinear;
  std::vector<double> x_, y_, second_derivatives_;
};

}  // namespace limber::multibody
