#include "results/shock_spectrum.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/error.h"

namespace limber::results {

namespace {

// Coefficients of y_k = b0 x_k + b1 x_{k−1} + b2 x_{k−2} + a1 y_{k−1} + a2 y_{k−2}
// (shock_spectrum.h).
struct RampInvariantFilter {
  double b0 = 0, b1 = 0, b2 = 0, a1 = 0, a2 = 0;
};

// 1 − sin(b)/b without the cancellation of small b (b ≥ 0): its series below 0.1 (terms to b¹⁰,
// truncation below 1e-18 relative; the direct form loses 1e-13 relative at 0.1).
double one_minus_sinc(double b) {
  if (b >= 0.1) return 1.0 - std::sin(b) / b;
  const double b2 = b * b;
  return b2 / 6.0 * (1.0 - b2 / 20.0 * (1.0 - b2 / 42.0 * (1.0 - b2 / 72.0 * (1.0 - b2 / 110.0))));
}

// Smallwood's coefficients for f_n [Hz], ζ and T = dt, each written so that the small
// differences of a low frequency (ωT ≪ 1, poles next to 1) keep their digits:
// b0 = (1 − E) + E (1 − sinc b), b2 = −E (1 − E) + E (1 − sinc b),
// b1 = 2E ((1 − cos b) − (1 − sinc b)).
RampInvariantFilter smallwood_filter(double f_hz, double zeta, double dt) {
  const double omega = 2.0 * std::numbers::pi * f_hz;
  const double a = zeta * omega * dt;
  const double b = omega * std::sqrt(1.0 - zeta * zeta) * dt;
  const double E = std::exp(-a);
  const double one_minus_E = -std::expm1(-a);
  const double c = one_minus_sinc(b);
  const double half_sin = std::sin(0.5 * b);
  RampInvariantFilter f;
  f.b0 = one_minus_E + E * c;
  f.b1 = 2.0 * E * (2.0 * half_sin * half_sin - c);
  f.b2 = -E * one_minus_E + E * c;
  f.a1 = 2.0 * E * std::cos(b);
  f.a2 = -E * E;
  return f;
}

// The largest |y| over [begin, end) of `y`, refined by the parabola through that sample and its
// neighbours in `y` (when it has both and |y| is concave there).
double refined_peak(const std::vector<double>& y, std::size_t begin, std::size_t end) {
  std::size_t k = begin;
  for (std::size_t i = begin; i < end; ++i) {
    if (std::abs(y[i]) > std::abs(y[k])) k = i;
  }
  const double peak = std::abs(y[k]);
  if (k == 0 || k + 1 >= y.size()) return peak;
  // Parabola through (−1, m), (0, p), (1, n) in |y| with the sign of y_k.
  const double s = y[k] < 0.0 ? -1.0 : 1.0;
  const double m = s * y[k - 1], p = s * y[k], n = s * y[k + 1];
  const double curvature = m - 2.0 * p + n;
  // A neighbour outside [begin, end) may be larger: then the peak is not here.
  if (curvature >= 0.0 || m > p || n > p) return peak;
  const double offset = 0.5 * (m - n) / curvature;  // in [−½, ½] since p is the largest
  return std::max(peak, p - 0.25 * (m - n) * offset);
}

}  // namespace

double srs_frequency_limit(double dt) { return 1.0 / (kSrsSamplesPerPeriod * dt); }

std::vector<double> srs_frequency_grid(double f_min_hz, double f_max_hz) {
  if (!(f_min_hz > 0.0) || !(f_max_hz >= f_min_hz) || !std::isfinite(f_max_hz)) {
    throw InputError(fmt::format("expected SRS frequencies 0 < min <= max, got min {:g} Hz, max {:g} Hz",
                                 f_min_hz, f_max_hz));
  }
  std::vector<double> grid;
  for (int k = 0;; ++k) {
    const double f = f_min_hz * std::exp2(static_cast<double>(k) / kSrsBandsPerOctave);
    if (f > f_max_hz * (1.0 + 1e-9)) break;
    grid.push_back(f);
  }
  return grid;
}

ShockSpectrum shock_response_spectrum(const Eigen::Ref<const Eigen::VectorXd>& acceleration, double dt,
                                      const std::vector<double>& frequencies_hz, double damping_ratio) {
  // Checks: the sampling, the damping, the band.
  const Eigen::Index n = acceleration.size();
  if (!(dt > 0.0) || !std::isfinite(dt)) throw InputError(fmt::format("expected a sample interval > 0 for an SRS, got {:g} s", dt));
  if (n < 2) throw InputError(fmt::format("expected at least 2 samples for an SRS, got {}", n));
  if (!(damping_ratio >= 0.0 && damping_ratio < 1.0)) {
    throw InputError(fmt::format("expected an SRS damping ratio in [0, 1), got {:g}", damping_ratio));
  }
  const double limit = srs_frequency_limit(dt);
  double f_lowest = limit;
  for (const double f : frequencies_hz) {
    if (!(f > 0.0) || f > limit * (1.0 + 1e-9)) {
      throw InputError(fmt::format(
          "expected SRS natural frequencies in (0, {:g}] Hz (fs/{:g} for samples {:g} s apart), got {:g} Hz",
          limit, kSrsSamplesPerPeriod, dt, f));
    }
    f_lowest = std::min(f_lowest, f);
  }
  // Residual: one period of the lowest natural frequency after the record.
  const auto residual = static_cast<std::size_t>(std::ceil(1.0 / (f_lowest * dt))) + 1;
  const std::size_t total = static_cast<std::size_t>(n) + residual;

  ShockSpectrum out;
  const auto nf = static_cast<Eigen::Index>(frequencies_hz.size());
  out.frequency_hz = Eigen::Map<const Eigen::VectorXd>(frequencies_hz.data(), nf);
  out.maximax.resize(nf);
  out.primary.resize(nf);
  out.residual.resize(nf);
  std::vector<double> y(total);
  const double first = acceleration(0), last = acceleration(n - 1);
  for (Eigen::Index j = 0; j < nf; ++j) {
    const RampInvariantFilter f = smallwood_filter(frequencies_hz[static_cast<std::size_t>(j)], damping_ratio, dt);
    // Start in equilibrium with the first sample: past inputs and outputs all x_0.
    double x1 = first, x2 = first, y1 = first, y2 = first;
    for (std::size_t k = 0; k < total; ++k) {
      const double x = k < static_cast<std::size_t>(n) ? acceleration(static_cast<Eigen::Index>(k)) : last;
      const double yk = f.b0 * x + f.b1 * x1 + f.b2 * x2 + f.a1 * y1 + f.a2 * y2;
      y[k] = yk;
      x2 = x1;
      x1 = x;
      y2 = y1;
      y1 = yk;
    }
    out.primary(j) = refined_peak(y, 0, static_cast<std::size_t>(n));
    out.residual(j) = refined_peak(y, static_cast<std::size_t>(n), total);
    out.maximax(j) = std::max(out.primary(j), out.residual(j));
  }
  return out;
}

}  // namespace limber::results
