// The shock response spectrum (results/shock_spectrum.h) against (a) the closed-form maximax SRS
// of an undamped oscillator under a half-sine base pulse and (b) a second method: the damped
// oscillator integrated directly by RK4 at a 50 times finer step, on a decaying-sine record.
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

TEST(ShockSpectrum, GridIsSixthOctavesUpToTheBandLimit) {
  const std::vector<double> grid = srs_frequency_grid(5.0, 10e3);
  // 5 Hz · 2^(k/6) ≤ 10 kHz: k ≤ 6 log2(2000) = 65.8.
  ASSERT_EQ(grid.size(), 66u);
  EXPECT_DOUBLE_EQ(grid.front(), 5.0);
  EXPECT_NEAR(grid[6], 10.0, 1e-12);
  EXPECT_NEAR(grid.back(), 5.0 * std::exp2(65.0 / 6.0), 1e-9);
  EXPECT_DOUBLE_EQ(srs_frequency_limit(1e-4), 1e3);
  EXPECT_THROW(srs_frequency_grid(0.0, 10.0), InputError);
  EXPECT_THROW(srs_frequency_grid(20.0, 10.0), InputError);
}

// (a) A 10 ms half-sine of 100 m/s², sampled at 100 kHz (the input between samples is a chord of
// the sine: off by at most A (Ω dt)²/8 = 1.2e-6 A), undamped, 5 Hz to fs/10 = 10 kHz.
// Tolerance 1 %: the ramp-invariant filter is exact for the piecewise-linear input, and the
// peak parabola finds a sinusoid's peak within 0.35 % at the top of the band (10 samples per
// period; far less below it).
TEST(ShockSpectrum, MatchesTheClosedFormOfAnUndampedHalfSine) {
  const double amplitude = 100.0, tau = 0.010, dt = 1e-5;
  const auto n = static_cast<Eigen::Index>(std::lround(tau / dt)) + 1;
  Eigen::VectorXd x(n);
  for (Eigen::Index k = 0; k < n; ++k) x(k) = amplitude * std::sin(kPi * static_cast<double>(k) * dt / tau);
  x(n - 1) = 0.0;  // sin π, without its round-off
  const std::vector<double> grid = srs_frequency_grid(5.0, srs_frequency_limit(dt));
  const ShockSpectrum srs = shock_response_spectrum(x, dt, grid, 0.0);
  ASSERT_EQ(srs.maximax.size(), static_cast<Eigen::Index>(grid.size()));
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
  RecordProperty("worst_relative_error", std::to_string(worst));
  std::printf("half-sine SRS: worst relative error over %zu frequencies %.3g\n", grid.size(), worst);
}

// (b) The second method: z̈ + 2ζω ż + ω² z = −x(t), y = −(2ζω ż + ω² z), integrated by
// classical RK4 at dt/50 with x the linear interpolation of the same samples (the input the
// ramp-invariant filter assumes), from rest, then one period of the lowest frequency with x held
// at the last sample; the peak is the largest |y| over the fine steps (at ≥ 500 steps per
// period it misses a peak by at most 1 − cos(π/500) = 2e-5).
double rk4_peak(const Eigen::VectorXd& x, double dt, double f, double zeta, double f_lowest) {
  const double omega = 2.0 * kPi * f;
  constexpr int kSubsteps = 50;
  const double h = dt / kSubsteps;
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

// A 200 Hz sine decaying over 20 ms, 0.1 s at 10 kHz, Q = 10. Tolerance 1 %: the filter's
// peak parabola is within 0.35 % at fs/10 (the top of the band), RK4 at ≥ 500 steps per period
// within 1e-6, its peak sampling within 2e-5.
TEST(ShockSpectrum, MatchesDirectIntegrationOfTheOscillatorOnADecayingSine) {
  const double dt = 1e-4, zeta = 1.0 / (2.0 * kDefaultSrsQ);
  const Eigen::Index n = 1001;
  Eigen::VectorXd x(n);
  for (Eigen::Index k = 0; k < n; ++k) {
    const double t = static_cast<double>(k) * dt;
    x(k) = 300.0 * std::exp(-t / 0.020) * std::sin(2.0 * kPi * 200.0 * t);
  }
  const std::vector<double> grid = srs_frequency_grid(kDefaultSrsMinFrequencyHz, srs_frequency_limit(dt));
  const ShockSpectrum srs = shock_response_spectrum(x, dt, grid, zeta);
  double worst = 0.0;
  for (std::size_t j = 0; j < grid.size(); ++j) {
    const double reference = rk4_peak(x, dt, grid[j], zeta, grid.front());
    const double value = srs.maximax(static_cast<Eigen::Index>(j));
    EXPECT_NEAR(value, reference, 0.01 * reference) << grid[j] << " Hz";
    worst = std::max(worst, std::abs(value - reference) / reference);
  }
  std::printf("decaying-sine SRS vs RK4: worst relative error over %zu frequencies %.3g\n", grid.size(), worst);
}

// A constant acceleration: the oscillator starts in equilibrium with it and the input holds it
// after the record, so every frequency sees exactly that acceleration (static gain 1).
TEST(ShockSpectrum, ConstantAccelerationIsItsOwnSpectrum) {
  const Eigen::VectorXd x = Eigen::VectorXd::Constant(500, -9.81);
  const ShockSpectrum srs = shock_response_spectrum(x, 1e-3, srs_frequency_grid(5.0, 100.0), 0.05);
  for (Eigen::Index j = 0; j < srs.maximax.size(); ++j) {
    EXPECT_NEAR(srs.maximax(j), 9.81, 1e-9 * 9.81);
    EXPECT_NEAR(srs.residual(j), 9.81, 1e-9 * 9.81);
  }
}

TEST(ShockSpectrum, RefusesABandTheSamplingCannotSupport) {
  const Eigen::VectorXd x = Eigen::VectorXd::Zero(100);
  // fs = 1 kHz supports up to 100 Hz.
  EXPECT_THROW(shock_response_spectrum(x, 1e-3, {50.0, 200.0}, 0.05), InputError);
  EXPECT_THROW(shock_response_spectrum(x, 0.0, {50.0}, 0.05), InputError);
  EXPECT_THROW(shock_response_spectrum(x, 1e-3, {50.0}, 1.0), InputError);
  EXPECT_THROW(shock_response_spectrum(Eigen::VectorXd::Zero(1), 1e-3, {50.0}, 0.05), InputError);
}

}  // namespace
}  // namespace limber::results
