// The maximax absolute-acceleration shock response spectrum (SRS) of a base acceleration
// history sampled at a constant interval dt (docs/shock-response-spectrum.md).
//
// For each natural frequency f_n the record drives a single-degree-of-freedom oscillator of
// damping ratio ζ = 1/(2Q) through its base: with x(t) the base acceleration and z the relative
// displacement, z̈ + 2ζω ż + ω² z = −x, ω = 2π f_n, and the oscillator's absolute acceleration
// y = −(2ζω ż + ω² z), H(s) = Y/X = (2ζω s + ω²)/(s² + 2ζω s + ω²). The spectrum is
// max_t |y(t)| (maximax: over the record and after it).
//
// The filter is Smallwood's ramp-invariant recursion (D. O. Smallwood, "An improved recursive
// formula for calculating shock response spectra", Shock and Vibration Bulletin 51, 1981; the
// method of ISO 18431-4:2007): exact when x is linear between samples. Derivation:
// H(s)/s² = 1/s² − 1/(s² + 2ζω s + ω²), whose sampled impulse response is kT − E^k sin(kb)/ω_d
// (a = ζωT, b = ω_d T, ω_d = ω √(1 − ζ²), E = e^{−a}, T = dt); the ramp-invariant transform
// H(z) = (z−1)²/(T z) · Z{that} gives, with S = E sin(b)/b,
//   y_k = b0 x_k + b1 x_{k−1} + b2 x_{k−2} + a1 y_{k−1} + a2 y_{k−2},
//   b0 = 1 − S,  b1 = 2 (S − E cos b),  b2 = E² − S,  a1 = 2 E cos b,  a2 = −E²
// (Smallwood's coefficients; the static gain Σb / (1 − a1 − a2) is exactly 1).
//
// Outside the record the base is taken to continue at the record's end values: before it the
// oscillator rests in equilibrium with the first sample (y = x_0, so a record that starts at 0
// starts the oscillator at rest), and after it the input holds the last sample while the filter
// runs on for the residual response, one period of the lowest natural frequency of the grid
// (the free vibration's largest peak comes within its first half period).
// The peak between samples is found by a parabola through the largest |y_k| and its two
// neighbours: at 10 samples per period that finds a sinusoid's peak within 0.35 % (the largest
// sample alone can miss it by 4.9 %).
//
// Band rule: natural frequencies up to fs/10 (kSamplesPerPeriod samples per period of f_n),
// where the ramp-invariant filter and the peak parabola hold the SRS within 0.35 % of the
// exact response to the piecewise-linear record. The record itself must resolve the
// acceleration it samples (content above fs/2 is aliased: no filter can undo that).
#pragma once

#include <Eigen/Core>

#include <vector>

namespace limber::results {

inline constexpr double kDefaultSrsMinFrequencyHz = 5.0;  // the usual lower end of spacecraft shock specifications
inline constexpr double kDefaultSrsQ = 10.0;              // amplification Q = 1/(2ζ), the usual shock value
inline constexpr int kSrsBandsPerOctave = 6;              // 1/6-octave grid
inline constexpr double kSrsSamplesPerPeriod = 10.0;      // band rule: f_n ≤ fs / 10

// The highest natural frequency the band rule allows for samples dt [s] apart: 1/(10 dt) [Hz].
double srs_frequency_limit(double dt);

// The 1/6-octave grid f_k = f_min 2^{k/6}, k = 0, 1, ... while f_k ≤ f_max (1e-9 relative
// slack, so a typed f_max on the grid is kept) [Hz]. Throws InputError unless
// 0 < f_min ≤ f_max.
std::vector<double> srs_frequency_grid(double f_min_hz, double f_max_hz);

// One record's spectrum over a frequency grid, in the record's units.
struct ShockSpectrum {
  Eigen::VectorXd frequency_hz;  // nf natural frequencies [Hz]
  Eigen::VectorXd maximax;       // nf, max |y| over the record and the residual
  Eigen::VectorXd primary;       // nf, max |y| during the record
  Eigen::VectorXd residual;      // nf, max |y| after the record (input held at its last sample)
};

// The SRS of `acceleration` (n ≥ 2 samples, dt [s] apart) at `frequencies_hz` with damping
// ratio `damping_ratio` (0 ≤ ζ < 1; Q = 10 is ζ = 0.05). Throws InputError when dt ≤ 0, n < 2,
// ζ is outside [0, 1), or a frequency is not positive or above srs_frequency_limit(dt).
ShockSpectrum shock_response_spectrum(const Eigen::Ref<const Eigen::VectorXd>& acceleration, double dt,
                                      const std::vector<double>& frequencies_hz, double damping_ratio);

}  // namespace limber::results
