#include "multibody/time_function.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "core/error.h"

namespace limber::multibody {

TimeFunction TimeFunction::constant(double value) {
  TimeFunction f;
  f.kind_ = Kind::kConstant;
  f.initial_ = value;
  return f;
}

TimeFunction TimeFunction::constant_speed(double initial, double speed) {
  TimeFunction f;
  f.kind_ = Kind::kConstantSpeed;
  f.initial_ = initial;
  f.speed_ = speed;
  return f;
}

TimeFunction TimeFunction::ramp(double initial, double speed, double duration, RampShape shape) {
  if (!(duration > 0.0)) {
    throw InputError(fmt::format("ramp duration: expected > 0 s, got {}", duration));
  }
  TimeFunction f;
  f.kind_ = Kind::kRamp;
  f.initial_ = initial;
  f.speed_ = speed;
  f.duration_ = duration;
  f.shape_ = shape;
  return f;
}

TimeFunction TimeFunction::table(std::vector<double> x, std::vector<double> y,
                                 TableInterpolation interpolation) {
  if (x.size() != y.size() || x.size() < 2) {
    throw InputError(fmt::format("table: expected ≥ 2 (x, y) pairs of equal count, got {} x and {} y",
                                 x.size(), y.size()));
  }
  for (size_t k = 1; k < x.size(); ++k) {
    if (!(x[k] > x[k - 1])) {
      throw InputError(fmt::format("table: expected increasing x, got x[{}] = {} after {}", k,
                                   x[k], x[k - 1]));
    }
  }
  TimeFunction f;
  f.kind_ = Kind::kTable;
  f.interpolation_ = interpolation;
  const size_t n = x.size();
  f.second_derivatives_.assign(n, 0.0);
  if (interpolation == TableInterpolation::kCubic && n > 2) {
    // Natural spline: tridiagonal system for the knot second derivatives (Thomas algorithm).
    std::vector<double> c(n, 0.0), d(n, 0.0);
    for (size_t k = 1; k + 1 < n; ++k) {
      const double h0 = x[k] - x[k - 1], h1 = x[k + 1] - x[k];
      const double a = h0 / 6.0, b = (h0 + h1) / 3.0, cc = h1 / 6.0;
      const double rhs = (y[k + 1] - y[k]) / h1 - (y[k] - y[k - 1]) / h0;
      const double denom = b - a * c[k - 1];
      c[k] = cc / denom;
      d[k] = (rhs - a * d[k - 1]) / denom;
    }
    for (size_t k = n - 2; k >= 1; --k) {
      f.second_derivatives_[k] = d[k] - c[k] * f.second_derivatives_[k + 1];
    }
  }
  f.x_ = std::move(x);
  f.y_ = std::move(y);
  return f;
}

namespace {

// Ramp shape s(τ), its integral S(τ) = ∫₀^τ s and derivative s'(τ).
FunctionValue ramp_shape(double tau, RampShape shape) {
  const double t2 = tau * tau, t3 = t2 * tau;
  if (shape == RampShape::kCubic) {
    return {t3 - 0.5 * t3 * tau, 3 * t2 - 2 * t3, 6 * tau - 6 * t2};
  }
  return {2.5 * t3 * tau - 3 * t3 * t2 + t3 * t3, 10 * t3 - 15 * t3 * tau + 6 * t3 * t2,
          30 * t2 - 60 * t3 + 30 * t3 * tau};
}

}  // namespace

FunctionValue TimeFunction::evaluate(double x) const {
  switch (kind_) {
    case Kind::kConstant:
      return {initial_, 0.0, 0.0};
    case Kind::kConstantSpeed:
      return {initial_ + speed_ * x, speed_, 0.0};
    case Kind::kRamp: {
      // Before the start: at rest; after the ramp: the integral of s over [0,1] is ½.
      if (x <= 0.0) return {initial_, 0.0, 0.0};
      if (x >= duration_) {
        return {initial_ + speed_ * (0.5 * duration_ + (x - duration_)), speed_, 0.0};
      }
      const FunctionValue s = ramp_shape(x / duration_, shape_);
      return {initial_ + speed_ * duration_ * s.value, speed_ * s.first,
              speed_ * s.second / duration_};
    }
    case Kind::kTable: {
      // Hold the end values outside the table; right-continuous derivatives: at x_0 those of
      // the first segment (a motion that starts there starts with its slope), at x_n zero.
      if (x < x_.front()) return {y_.front(), 0.0, 0.0};
      if (x >= x_.back()) return {y_.back(), 0.0, 0.0};
      const size_t k = std::min<size_t>(std::upper_bound(x_.begin(), x_.end(), x) - x_.begin() - 1, x_.size() - 2);
      const double h = x_[k + 1] - x_[k];
      const double a = (x_[k + 1] - x) / h, b = (x - x_[k]) / h;
      const double slope = (y_[k + 1] - y_[k]) / h;
      if (interpolation_ == TableInterpolation::kLinear) return {a * y_[k] + b * y_[k + 1], slope, 0.0};
      // Cubic spline segment (Press et al., Numerical Recipes, §3.3).
      const double m0 = second_derivatives_[k], m1 = second_derivatives_[k + 1];
      const double value =
          a * y_[k] + b * y_[k + 1] + ((a * a * a - a) * m0 + (b * b * b - b) * m1) * h * h / 6.0;
      const double first = slope - (3 * a * a - 1) * h * m0 / 6.0 + (3 * b * b - 1) * h * m1 / 6.0;
      return {value, first, a * m0 + b * m1};
    }
  }
  return {};
}

std::vector<double> TimeFunction::slope_jumps() const {
  if (kind_ != Kind::kTable) return {};
  // One-sided slopes at x_k: the segment before and after (zero outside the table).
  const size_t n = x_.size();
  const auto slope_after = [&](size_t k) {
    if (k + 1 >= n) return 0.0;
    const double h = x_[k + 1] - x_[k];
    const double secant = (y_[k + 1] - y_[k]) / h;
    if (interpolation_ == TableInterpolation::kLinear) return secant;
    return secant - h * (2.0 * second_derivatives_[k] + second_derivatives_[k + 1]) / 6.0;
  };
  const auto slope_before = [&](size_t k) {
    if (k == 0) return 0.0;
    const double h = x_[k] - x_[k - 1];
    const double secant = (y_[k] - y_[k - 1]) / h;
    if (interpolation_ == TableInterpolation::kLinear) return secant;
    return secant + h * (second_derivatives_[k - 1] + 2.0 * second_derivatives_[k]) / 6.0;
  };
  // A jump is a difference beyond rounding of the slopes' size.
  std::vector<double> jumps;
  for (size_t k = 0; k < n; ++k) {
    const double before = slope_before(k), after = slope_after(k);
    const double size = std::max({std::abs(before), std::abs(after), 1e-300});
    if (std::abs(after - before) > 1e-12 * size) jumps.push_back(x_[k]);
  }
  return jumps;
}

}  // namespace limber::multibody
