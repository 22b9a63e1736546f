// The shock response spectrum (results/shock_spectrum.h) against (a) the closed-form maximax SRS
// of an undamped oscillator under a half-sine base pulse and (b) a second method: the damped
// oscillator integrated directly by RK4 at a 50 times finer step, on a decaying-sine record;
// each on a uniform record and on a variable-step one (an integrator's steps).
#include "results/shock_spectrum.h"

#include "core/error.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

namespace limber::results {
namespace {

constexpr double kPi = std::numbers::pi;

// Closed form, undamped (Harris' Shock and Vibration Handbook, ch. 8, derived here): base
// pulse x = A sin(Ωt) on [0, τ], Ω = π/τ, oscillator ω = 2π f, β = Ω/ω. The absolute
// acceleration obeys ÿ + ω² y = ω² x, so from rest
//   primary (t ≤ τ):  y = A/(1 − β²) (sin Ωt − β sin ωt),
// whose stationary points satisfy cos Ωt = cos ωt: t = 2πn/(ω + Ω) or 2πn/(ω − Ω), plus the
// end t = τ; after the pulse the free vibration's amplitude is
//   residual:         √(y(τ)² + (ẏ(τ)/ω)²) = 2Aβ |cos(π/(2β))| / |1 − β²|.
// (β ≠ 1: the grid below never hits resonance exactly.)
struct HalfSineSrs {
  double primary = 0.0, residual = 0.0;
};
HalfSineSrs half_sine_srs(double amplitude, double tau, double f) {
  const double Omega = kPi / tau, omega = 2.0 * kPi * f, beta = Omega / omega;
  const auto y = [&](double t) {
    return amplitude / (1.0 - beta * beta) * (std::sin(Omega * t) - beta * std::sin(omega * t));
  };
  HalfSineSrs out;
  out.primary = std::abs(y(tau));
  for (const double rate : {omega + Omega, std::abs(omega - Omega)}) {
    for (int n = 1; 2.0 * kPi * n / rate <= tau; ++n) out.primary = std::max(out.primary, std::abs(y(2.0 * kPi * n / rate)));
  }
  out.residual = 2.0 * amplitude * beta * std::abs(std::cos(kPi / (2.0 * beta))) / std::abs(1.0 - beta * beta);
  return out;
}

// Times k dt, k = 0 .. n − 1.
Eigen::VectorXd uniform_times(Eigen::Index n, double dt) {
  Eigen::VectorXd t(n);
  for (Eigen::Index k = 0; k < n; ++k) t(k) = static_cast<double>(k) * dt;
  return t;
}

// Times from 0 to t_end whose steps cycle through fractions of `longest` (1, 1/4, 0.6, 1/8,
// 0.4: as an integrator cuts its step at events and in event windows), the last step cut to
// end at t_end.
Eigen::VectorXd variable_times(double t_end, double longest) {
  constexpr double kFractions[] = {1.0, 0.25, 0.6, 0.125, 0.4};
  std::vector<double> t{0.0};
  for (std::size_t k = 0; t.back() < t_end - 1e-12 * t_end; ++k) {
    t.push_back(std::min(t_end, t.back() + longest * kFractions[k % std::size(kFractions)]));
  }
  return Eigen::Map<const Eigen::VectorXd>(t.data(), static_cast<Eigen::Index>(t.size()));
}

TEST(ShockSpectrum, GridIsSixthOctavesUpToTheBandLimit) {
  const std::vector<double> grid = srs_frequency_grid(5.0, 10e3);
  // 5 Hz · 2^(k/6) ≤ 10 kHz: k ≤ 6 log2(2000) = 65.8.
  ASSERT_EQ(grid.size(), 66u);
  EXPECT_DOUBLE_EQ(grid.front(), 5.0);
  EXPECT_NEAR(grid[6], 10.0, 1e-12);
  EXPECT_NEAR(grid.back(), 5.0 * std::exp2(65.0 / 6.0), 1e-9);
  EXPECT_DOUBLE_EQ(srs_frequency_limit(1e-4), 1e3);
  // The longest step of a record with one step of 2 ms among steps of 1 ms.
  Eigen::VectorXd time = uniform_times(100, 1e-3);
  time.tail(50).array() += 1e-3;
  EXPECT_NEAR(longest_step(time), 2e-3, 1e-15);
  EXPECT_THROW(srs_frequency_grid(0.0, 10.0), InputError);
  EXPECT_THROW(srs_frequency_grid(20.0, 10.0), InputError);
}

// (a) A 10 ms half-sine of 100 m/s² recorded at `time` (the input between points is a chord of
// the sine: off by at most A (Ω h)²/8 = 1.2e-6 A at h = 10 µs), undamped, 5 Hz to 1/(10 h_max)
// = 10 kHz. Tolerance 1 %: the filter is exact for the piecewise-linear input, and the peak
// parabola finds a sinusoid's peak within 0.35 % at 10 points per period (far less below).
double half_sine_worst_error(const Eigen::VectorXd& time) {
  const double amplitude = 100.0, tau = 0.010;
  Eigen::VectorXd x(time.size());
  for (Eigen::Index k = 0; k < time.size(); ++k) x(k) = amplitude * std::sin(kPi * time(k) / tau);
  x(x.size() - 1) = 0.0;  // sin π, without its round-off
  const std::vector<double> grid = srs_frequency_grid(5.0, srs_frequency_limit(longest_step(time)));
  const ShockSpectrum srs = shock_response_spectrum(time, x, grid, 0.0);
  EXPECT_EQ(srs.maximax.size(), static_cast<Eigen::Index>(grid.size()));
  double worst = 0.0;
  for (std::size_t j = 0; j < grid.size(); ++j) {
    const HalfSineSrs exact = half_sine_srs(amplitude, tau, grid[j]);
    const auto i = static_cast<Eigen::Index>(j);
    const double maximax = std::max(exact.primary, exact.residual);
    EXPECT_NEAR(srs.maximax(i), maximax, 0.01 * maximax) << grid[j] << " Hz";
    EXPECT_NEAR(srs.primary(i), exact.primary, 0.01 * maximax) << grid[j] << " Hz";
    EXPECT_NEAR(srs.residual(i), exact.residual, 0.01 * maximax) << grid[j] << " Hz";
    worst = std::max(worst, std::abs(srs.maximax(i) - maximax) / maximax);
  }
  // Shape checks of the closed form itself: the low end is the residual of a pulse short
  // against the period (≈ 4 A f τ), the high end follows the input (≈ A).
  EXPECT_NEAR(srs.maximax(0), 4.0 * amplitude * grid[0] * tau, 0.01 * srs.maximax(0));
  EXPECT_NEAR(srs.maximax(srs.maximax.size() - 1), amplitude, 0.01 * amplitude);
  return worst;
}

TEST(ShockSpectrum, MatchesTheClosedFormOfAnUndampedHalfSine) {
  const double worst = half_sine_worst_error(uniform_times(1001, 1e-5));
  RecordProperty("worst_relative_error", std::to_string(worst));
  std::printf("half-sine SRS, uniform 10 us: worst relative error %.3g\n", worst);
}

// The same pulse recorded at steps of 1.25 to 10 µs (band 10 kHz as above).
TEST(ShockSpectrum, MatchesTheClosedFormOfAnUndampedHalfSineOnVariableSteps) {
  const Eigen::VectorXd time = variable_times(0.010, 1e-5);
  ASSERT_NEAR(longest_step(time), 1e-5, 1e-18);
  const double worst = half_sine_worst_error(time);
  RecordProperty("worst_relative_error", std::to_string(worst));
  std::printf("half-sine SRS, %ld variable steps: worst relative error %.3g\n", static_cast<long>(time.size() - 1),
              worst);
}

// (b) The second method: z̈ + 2ζω ż + ω² z = −x(t), y = −(2ζω ż + ω² z), integrated by
// classical RK4 at 1/50 of each step with x the linear interpolation of the same points (the
// input the ramp-invariant filter assumes), from rest, then one period of the lowest frequency
// with x held at the last point; the peak is the largest |y| over the fine steps (at ≥ 500 steps per
// period it misses a peak by at most 1 − cos(π/500) = 2e-5).
double rk4_peak(const Eigen::VectorXd& time, const Eigen::VectorXd& x, double f, double zeta, double f_lowest) {
  const double omega = 2.0 * kPi * f;
  constexpr int kSubsteps = 50;
  const double dt = longest_step(time);
  const auto n = x.size();
  const auto total = n - 1 + static_cast<Eigen::Index>(std::ceil(1.0 / (f_lowest * dt))) + 1;
  const auto input = [&](Eigen::Index k, double s) {  // s in [0, 1] within interval k
    const double a = x(std::min(k, n - 1)), b = x(std::min(k + 1, n - 1));
    return a + (b - a) * s;
  };
  const auto rate = [&](double z, double w, double xin, double& dz, double& dw) {
    dz = w;
    dw = -xin - 2.0 * zeta * omega * w - omega * omega * z;
  };
  double z = 0.0, w = 0.0, peak = 0.0;
  for (Eigen::Index k = 0; k < total; ++k) {
    // The record's steps, then steps of its longest one with x held.
    const double h = (k + 1 < n ? time(k + 1) - time(k) : dt) / kSubsteps;
    for (int s = 0; s < kSubsteps; ++s) {
      const double s0 = static_cast<double>(s) / kSubsteps, s1 = static_cast<double>(s + 1) / kSubsteps;
      const double x0 = input(k, s0), xm = input(k, 0.5 * (s0 + s1)), x1 = input(k, s1);
      double k1z, k1w, k2z, k2w, k3z, k3w, k4z, k4w;
      rate(z, w, x0, k1z, k1w);
      rate(z + 0.5 * h * k1z, w + 0.5 * h * k1w, xm, k2z, k2w);
      rate(z + 0.5 * h * k2z, w + 0.5 * h * k2w, xm, k3z, k3w);
      rate(z + h * k3z, w + h * k3w, x1, k4z, k4w);
      z += h / 6.0 * (k1z + 2.0 * k2z + 2.0 * k3z + k4z);
      w += h / 6.0 * (k1w + 2.0 * k2w + 2.0 * k3w + k4w);
      peak = std::max(peak, std::abs(2.0 * zeta * omega * w + omega * omega * z));
    }
  }
  return peak;
}

// A 200 Hz sine decaying over 20 ms, 0.1 s recorded at `time`, Q = 10, 5 Hz to 1/(10 h_max).
// Tolerance 1 %: the filter's peak parabola is within 0.35 % at 10 points per period, RK4 at
// ≥ 500 steps per period within 1e-6, its peak sampling within 2e-5.
double decaying_sine_worst_error(const Eigen::VectorXd& time) {
  const double zeta = 1.0 / (2.0 * kDefaultSrsQ);
  Eigen::VectorXd x(time.size());
  for (Eigen::Index k = 0; k < time.size(); ++k) {
    x(k) = 300.0 * std::exp(-time(k) / 0.020) * std::sin(2.0 * kPi * 200.0 * time(k));
  }
  const double f_max = srs_frequency_limit(longest_step(time));
  const std::vector<double> grid = srs_frequency_grid(kDefaultSrsMinFrequencyHz, f_max);
  const ShockSpectrum srs = shock_response_spectrum(time, x, grid, zeta);
  double worst = 0.0;
  for (std::size_t j = 0; j < grid.size(); ++j) {
    const double reference = rk4_peak(time, x, grid[j], zeta, grid.front());
    const double value = srs.maximax(static_cast<Eigen::Index>(j));
    EXPECT_NEAR(value, reference, 0.01 * reference) << grid[j] << " Hz";
    worst = std::max(worst, std::abs(value - reference) / reference);
  }
  return worst;
}

TEST(ShockSpectrum, MatchesDirectIntegrationOfTheOscillatorOnADecayingSine) {
  const double worst = decaying_sine_worst_error(uniform_times(1001, 1e-4));
  std::printf("decaying-sine SRS vs RK4, uniform 0.1 ms: worst relative error %.3g\n", worst);
}

// The same at steps of 12.5 to 100 µs.
TEST(ShockSpectrum, MatchesDirectIntegrationOfTheOscillatorOnVariableSteps) {
  const double worst = decaying_sine_worst_error(variable_times(0.1, 1e-4));
  std::printf("decaying-sine SRS vs RK4, variable steps: worst relative error %.3g\n", worst);
}

// A jump of the input (two points at one time, as at a release): the record is a step of A at
// t = 0.1 s, and an undamped oscillator's absolute acceleration A (1 − cos ωt) peaks at 2A
// half a period later (within the 0.1 s left for f ≥ 5 Hz). Tolerance 1 %: the parabola
// through 10 points per period finds the cosine's top within 0.35 % of its amplitude A.
TEST(ShockSpectrum, AJumpOfTheInputIsAStep) {
  std::vector<double> t, x;
  for (int k = 0; k <= 200; ++k) {
    t.push_back(1e-3 * k);
    x.push_back(k > 100 ? 50.0 : 0.0);
    if (k == 100) {
      t.push_back(t.back());
      x.push_back(50.0);
    }
  }
  const Eigen::Map<const Eigen::VectorXd> time(t.data(), static_cast<Eigen::Index>(t.size()));
  const Eigen::Map<const Eigen::VectorXd> record(x.data(), static_cast<Eigen::Index>(x.size()));
  const ShockSpectrum srs = shock_response_spectrum(time, record, srs_frequency_grid(5.0, 100.0), 0.0);
  for (Eigen::Index j = 0; j < srs.maximax.size(); ++j) EXPECT_NEAR(srs.maximax(j), 100.0, 1.0) << srs.frequency_hz(j);
}

// A constant acceleration: the oscillator starts in equilibrium with it and the input holds it
// after the record, so every frequency sees exactly that acceleration (static gain 1).
TEST(ShockSpectrum, ConstantAccelerationIsItsOwnSpectrum) {
  const Eigen::VectorXd x = Eigen::VectorXd::Constant(500, -9.81);
  const ShockSpectrum srs = shock_response_spectrum(uniform_times(500, 1e-3), x, srs_frequency_grid(5.0, 100.0), 0.05);
  for (Eigen::Index j = 0; j < srs.maximax.size(); ++j) {
    EXPECT_NEAR(srs.maximax(j), 9.81, 1e-9 * 9.81);
    EXPECT_NEAR(srs.residual(j), 9.81, 1e-9 * 9.81);
  }
}

TEST(ShockSpectrum, RefusesABadRecord) {
  const Eigen::VectorXd x = Eigen::VectorXd::Zero(100);
  const Eigen::VectorXd time = uniform_times(100, 1e-3);
  EXPECT_NO_THROW(shock_response_spectrum(time, x, {50.0}, 0.05));
  EXPECT_THROW(shock_response_spectrum(time, x, {0.0}, 0.05), InputError);
  EXPECT_THROW(shock_response_spectrum(Eigen::VectorXd::Zero(100), x, {50.0}, 0.05), InputError);  // no time
  EXPECT_THROW(shock_response_spectrum(time.reverse(), x, {50.0}, 0.05), InputError);
  EXPECT_THROW(shock_response_spectrum(time, x, {50.0}, 1.0), InputError);
  EXPECT_THROW(shock_response_spectrum(time.head(1), x.head(1), {50.0}, 0.05), InputError);
}

}  // namespace
}  // namespace limber::results
