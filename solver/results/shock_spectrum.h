// The maximax absolute-acceleration shock response spectrum (SRS) of a base acceleration
// history recorded at increasing times, uniform or not (an integrator's steps;
// docs/shock-response-spectrum.md).
//
// For each natural frequency f_n the record drives a single-degree-of-freedom oscillator of
// damping ratio ζ = 1/(2Q) through its base: with x(t) the base acceleration and z the relative
// displacement, z̈ + 2ζω ż + ω² z = −x, ω = 2π f_n, and the oscillator's absolute acceleration
// y = −(2ζω ż + ω² z), H(s) = Y/X = (2ζω s + ω²)/(s² + 2ζω s + ω²). The spectrum is
// max_t |y(t)| (maximax: over the record and after it).
//
// The filter is the exact response to the record taken linear between its points (the
// ramp-invariant or first-order-hold discretisation: D. O. Smallwood, "An improved recursive
// formula for calculating shock response spectra", Shock and Vibration Bulletin 51, 1981; the
// method of ISO 18431-4:2007), written as a state update with coefficients per step so that
// the steps may differ: in θ = ω t and the state s = (u, w) = (ω² z, ω ż),
//   ds/dθ = M s − (0, x),   M = [[0, 1], [−1, −2ζ]],   y = −(u + 2ζ w),
// and over a step of length h (Θ = ω h) with x linear from x_a to x_b,
//   s_b = Φ s_a + Γ_a x_a + Γ_b x_b,   Φ = e^{MΘ},
//   Γ_b = −(Ψ1 − Ψ2) e₂,  Γ_a = −Ψ2 e₂,
//   Ψ1 = ∫₀^Θ e^{Mσ} dσ,  Ψ2 = (1/Θ) ∫₀^Θ σ e^{Mσ} dσ.
// On a uniform record this is Smallwood's recursion (the same exact response). A zero-length
// step (two points at one time: a jump of x, as at a release) leaves the state as it is.
//
// Outside the record the base is taken to continue at the record's end values: before it the
// oscillator rests in equilibrium with the first point (y = x_0, so a record that starts at 0
// starts the oscillator at rest), and after it the input holds the last point while the filter
// runs on for the residual response, one period of the lowest natural frequency asked for
// (the free vibration's largest peak comes within its first half period).
// Peaks between points: a step longer than a twentieth of the oscillator's period is cut into
// equal sub-steps (x linear within it, so the response there is still exact), and each local
// maximum of |y| is refined by the parabola through it and its two neighbours: at 20 points per
// period that finds a sinusoid's peak within 0.02 % (0.35 % at 10, where the largest point
// alone can miss it by 4.9 %).
//
// Band rule: natural frequencies up to 1/(10 h_max), h_max the record's longest step
// (kSrsSamplesPerPeriod points per period of f_n). The filter itself is exact at any frequency;
// the rule is about the record: between its points it is a chord, and an integrator's step
// resolves a vibration only with several steps per period (generalized-α's period error is
// (ωh)²/12, 3.3 % at 10 steps per period). Content the record does not resolve is not in it.
#pragma once

#include <Eigen/Core>

#include <vector>

namespace limber::results {

inline constexpr double kDefaultSrsMinFrequencyHz = 5.0;  // the usual lower end of spacecraft shock specifications
inline constexpr double kDefaultSrsQ = 10.0;              // amplification Q = 1/(2ζ), the usual shock value
inline constexpr int kSrsBandsPerOctave = 6;              // 1/6-octave grid
inline constexpr double kSrsSamplesPerPeriod = 10.0;      // band rule: f_n ≤ 1/(10 h_max)

// The highest natural frequency the band rule allows for a record whose longest step is
// `longest_step` [s]: 1/(10 longest_step) [Hz].
double srs_frequency_limit(double longest_step);

// The longest positive step of `time` (non-decreasing) [s]; 0 for fewer than 2 distinct times.
double longest_step(const Eigen::Ref<const Eigen::VectorXd>& time);

// The 1/6-octave grid f_k = f_min 2^{k/6}, k = 0, 1, ... while f_k ≤ f_max (1e-9 relative
// slack, so a typed f_max on the grid is kept) [Hz]. Throws InputError unless
// 0 < f_min ≤ f_max.
std::vector<double> srs_frequency_grid(double f_min_hz, double f_max_hz);

// One record's spectrum over a frequency grid, in the record's units.
struct ShockSpectrum {
  Eigen::VectorXd frequency_hz;  // nf natural frequencies [Hz]
  Eigen::VectorXd maximax;       // nf, max |y| over the record and the residual
  Eigen::VectorXd primary;       // nf, max |y| during the record
  Eigen::VectorXd residual;      // nf, max |y| after the record (input held at its last point)
};

// The SRS of each column of `acceleration` (n rows, one per entry of `time` [s], which does
// not decrease and spans a positive time) at `frequencies_hz` with damping ratio
// `damping_ratio` (0 ≤ ζ < 1; Q = 10 is ζ = 0.05); the coefficients of each step are shared by
// the columns. The band rule is the caller's (shock_spectra.h): the filter is exact at any
// frequency. Throws InputError when the times decrease or span no time, the sizes differ, ζ
// is outside [0, 1), or a frequency is not positive.
std::vector<ShockSpectrum> shock_response_spectra(const Eigen::Ref<const Eigen::VectorXd>& time,
                                                  const Eigen::Ref<const Eigen::MatrixXd>& acceleration,
                                                  const std::vector<double>& frequencies_hz, double damping_ratio);

// One column: shock_response_spectra(time, acceleration, ...)[0].
ShockSpectrum shock_response_spectrum(const Eigen::Ref<const Eigen::VectorXd>& time,
                                      const Eigen::Ref<const Eigen::VectorXd>& acceleration,
                                      const std::vector<double>& frequencies_hz, double damping_ratio);

}  // namespace limber::results
