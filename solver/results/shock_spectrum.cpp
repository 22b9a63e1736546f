#include "results/shock_spectrum.h"

#include <fmt/format.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "core/error.h"

namespace limber::results {

namespace {

// Below this Θ = ωh the coefficients come from the exponential's series: the closed form
// divides by Θ and loses digits to cancellation (1 − Φ ≈ MΘ).
constexpr double kSeriesBelow = 0.5;
// Terms of the series: ‖MΘ‖ < 1.5 below kSeriesBelow, and 1.5^30/30! < 1e-23.
constexpr int kSeriesTerms = 30;
// Points per period of the oscillator at which its response is evaluated (a longer step is cut
// into sub-steps): the peak parabola then finds a sinusoid's top within 0.02 % (0.35 % at 10).
constexpr double kPeakPointsPerPeriod = 20.0;

// One step's update s_b = Φ s_a + Γ_a x_a + Γ_b x_b (shock_spectrum.h), s = (ω² z, ω ż).
struct StepFilter {
  Eigen::Matrix2d phi;
  Eigen::Vector2d gamma_a, gamma_b;
};

// The update over Θ = ω h for damping ratio ζ.
StepFilter step_filter(double theta, double zeta) {
  StepFilter f;
  if (theta < kSeriesBelow) {
    // Φ = Σ (MΘ)^k/k!, Ψ1 e₂ = Θ Σ (MΘ)^k e₂/(k+1)!, Ψ2 e₂ = Θ Σ (MΘ)^k e₂/(k! (k+2)).
    Eigen::Matrix2d m;
    m << 0.0, 1.0, -1.0, -2.0 * zeta;
    m *= theta;
    Eigen::Matrix2d power = Eigen::Matrix2d::Identity();
    Eigen::Vector2d psi1 = Eigen::Vector2d::Zero(), psi2 = Eigen::Vector2d::Zero();
    f.phi.setZero();
    double factorial = 1.0;  // k!
    for (int k = 0; k < kSeriesTerms; ++k) {
      f.phi += power / factorial;
      psi1 += theta * power.col(1) / (factorial * (k + 1));
      psi2 += theta * power.col(1) / (factorial * (k + 2));
      power = m * power;
      factorial *= k + 1;
    }
    f.gamma_b = -(psi1 - psi2);
    f.gamma_a = -psi2;
    return f;
  }
  // Closed form: Φ of the damped oscillator; Γ from the particular solution of a ramp,
  // s_p = (−x + 2ζ d, −d) with d the slope per unit θ: Γ = s_p(Θ) − Φ s_p(0) for x = 0 → 1
  // (Γ_b) and 1 → 0 (Γ_a).
  const double nu = std::sqrt(1.0 - zeta * zeta);
  const double E = std::exp(-zeta * theta), c = std::cos(nu * theta), s = std::sin(nu * theta);
  f.phi << E * (c + zeta / nu * s), E * s / nu, -E * s / nu, E * (c - zeta / nu * s);
  const double d = 1.0 / theta;
  f.gamma_b = Eigen::Vector2d(-1.0 + 2.0 * zeta * d, -d) - f.phi * Eigen::Vector2d(2.0 * zeta * d, -d);
  f.gamma_a = Eigen::Vector2d(-2.0 * zeta * d, d) - f.phi * Eigen::Vector2d(-1.0 - 2.0 * zeta * d, d);
  return f;
}

// The vertex of the parabola through (t_{k−1}, m), (t_k, p), (t_{k+1}, n) in |y| (the sign of
// y_k applied), when |y| is concave there with p the largest: m + s0 τ + c τ (τ − h0),
// τ = t − t_{k−1}, at s0 + c (2τ − h0) = 0. Sets `at` to its time; false when not concave.
bool parabola_peak(const std::vector<double>& t, const std::vector<double>& y, std::size_t k, double& value,
                   double& at) {
  const double sign = y[k] < 0.0 ? -1.0 : 1.0;
  const double m = sign * y[k - 1], p = sign * y[k], n = sign * y[k + 1];
  if (m > p || n > p) return false;
  const double h0 = t[k] - t[k - 1], h1 = t[k + 1] - t[k];
  const double s0 = (p - m) / h0, s1 = (n - p) / h1;
  const double c = (s1 - s0) / (h0 + h1);
  if (!(c < 0.0)) return false;
  const double tau = 0.5 * h0 - 0.5 * s0 / c;
  value = m + s0 * tau + c * tau * (tau - h0);
  at = t[k - 1] + tau;
  return true;
}

// The largest |y| over the points [begin, end) of (t, y), each local maximum refined by its
// parabola when the vertex falls within the range's time span (one beyond it belongs to the
// neighbouring range: the primary's last point may rise into the residual).
double refined_peak(const std::vector<double>& t, const std::vector<double>& y, std::size_t begin,
                    std::size_t end) {
  double peak = 0.0;
  for (std::size_t k = begin; k < end; ++k) {
    peak = std::max(peak, std::abs(y[k]));
    if (k == 0 || k + 1 >= y.size()) continue;
    double value = 0.0, at = 0.0;
    if (parabola_peak(t, y, k, value, at) && at >= t[begin] && at <= t[end - 1]) peak = std::max(peak, value);
  }
  return peak;
}

void check_record(const Eigen::Ref<const Eigen::VectorXd>& time, Eigen::Index rows, double damping_ratio) {
  if (time.size() != rows) {
    throw InputError(fmt::format("expected one acceleration row per time for an SRS, got {} times and {} rows",
                                 time.size(), rows));
  }
  if (time.size() < 2 || !(time(time.size() - 1) > time(0))) {
    throw InputError(fmt::format("expected an SRS record spanning a positive time, got {} points", time.size()));
  }
  for (Eigen::Index k = 1; k < time.size(); ++k) {
    if (!(time(k) >= time(k - 1))) {
      throw InputError(fmt::format("expected SRS record times that do not decrease, got {:.17g} s after {:.17g} s",
                                   time(k), time(k - 1)));
    }
  }
  if (!(damping_ratio >= 0.0 && damping_ratio < 1.0)) {
    throw InputError(fmt::format("expected an SRS damping ratio in [0, 1), got {:g}", damping_ratio));
  }
}

}  // namespace

double srs_frequency_limit(double longest_step) { return 1.0 / (kSrsSamplesPerPeriod * longest_step); }

double longest_step(const Eigen::Ref<const Eigen::VectorXd>& time) {
  double longest = 0.0;
  for (Eigen::Index k = 1; k < time.size(); ++k) longest = std::max(longest, time(k) - time(k - 1));
  return longest;
}

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

std::vector<ShockSpectrum> shock_response_spectra(const Eigen::Ref<const Eigen::VectorXd>& time,
                                                  const Eigen::Ref<const Eigen::MatrixXd>& acceleration,
                                                  const std::vector<double>& frequencies_hz, double damping_ratio) {
  // Checks: the record, the damping, the frequencies.
  check_record(time, acceleration.rows(), damping_ratio);
  double f_lowest = std::numeric_limits<double>::infinity();
  for (const double f : frequencies_hz) {
    if (!(f > 0.0) || !std::isfinite(f)) {
      throw InputError(fmt::format("expected SRS natural frequencies > 0, got {:g} Hz", f));
    }
    f_lowest = std::min(f_lowest, f);
  }
  const Eigen::Index n = time.size(), columns = acceleration.cols();
  const auto nf = static_cast<Eigen::Index>(frequencies_hz.size());
  std::vector<ShockSpectrum> out(static_cast<std::size_t>(columns));
  for (ShockSpectrum& spectrum : out) {
    spectrum.frequency_hz = Eigen::Map<const Eigen::VectorXd>(frequencies_hz.data(), nf);
    spectrum.maximax.resize(nf);
    spectrum.primary.resize(nf);
    spectrum.residual.resize(nf);
  }
  std::vector<double> t_points;
  std::vector<std::vector<double>> y_points(static_cast<std::size_t>(columns));
  const Eigen::RowVectorXd first = acceleration.row(0), last = acceleration.row(n - 1);
  for (Eigen::Index j = 0; j < nf; ++j) {
    const double f = frequencies_hz[static_cast<std::size_t>(j)];
    const double omega = 2.0 * std::numbers::pi * f;
    const double longest_sub_step = 1.0 / (kPeakPointsPerPeriod * f);
    // Start in equilibrium with the first point: u = −x_0, w = 0 (y = x_0).
    Eigen::Matrix2Xd s = Eigen::Matrix2Xd::Zero(2, columns);
    s.row(0) = -first;
    t_points.assign(1, time(0));
    for (Eigen::Index c = 0; c < columns; ++c) y_points[static_cast<std::size_t>(c)].assign(1, first(c));
    // Advances every column by `steps` equal sub-steps of length h with x linear from x_a to x_b.
    double cached_theta = -1.0;
    StepFilter filter;
    const auto advance = [&](double t_a, double h, int steps, const Eigen::RowVectorXd& x_a,
                             const Eigen::RowVectorXd& x_b) {
      const double theta = omega * h / steps;
      if (theta != cached_theta) filter = step_filter(theta, damping_ratio);
      cached_theta = theta;
      for (int i = 1; i <= steps; ++i) {
        const double r0 = static_cast<double>(i - 1) / steps, r1 = static_cast<double>(i) / steps;
        t_points.push_back(t_a + h * r1);
        for (Eigen::Index c = 0; c < columns; ++c) {
          const double xa = x_a(c) + (x_b(c) - x_a(c)) * r0, xb = x_a(c) + (x_b(c) - x_a(c)) * r1;
          s.col(c) = filter.phi * s.col(c) + filter.gamma_a * xa + filter.gamma_b * xb;
          y_points[static_cast<std::size_t>(c)].push_back(-(s(0, c) + 2.0 * damping_ratio * s(1, c)));
        }
      }
    };
    // The record, step by step; a zero-length step only switches x.
    for (Eigen::Index k = 0; k + 1 < n; ++k) {
      const double h = time(k + 1) - time(k);
      if (h <= 0.0) continue;
      const int steps = std::max(1, static_cast<int>(std::ceil(h / longest_sub_step * (1.0 - 1e-9))));
      advance(time(k), h, steps, acceleration.row(k), acceleration.row(k + 1));
    }
    const std::size_t primary_end = t_points.size();
    // Residual: the last point held for one period of the lowest frequency (and one sub-step).
    const int residual_steps = static_cast<int>(std::ceil(f / f_lowest * kPeakPointsPerPeriod)) + 1;
    advance(time(n - 1), residual_steps * longest_sub_step, residual_steps, last, last);
    for (Eigen::Index c = 0; c < columns; ++c) {
      const std::vector<double>& y = y_points[static_cast<std::size_t>(c)];
      ShockSpectrum& spectrum = out[static_cast<std::size_t>(c)];
      spectrum.primary(j) = refined_peak(t_points, y, 0, primary_end);
      spectrum.residual(j) = refined_peak(t_points, y, primary_end, y.size());
      spectrum.maximax(j) = std::max(spectrum.primary(j), spectrum.residual(j));
    }
  }
  return out;
}

ShockSpectrum shock_response_spectrum(const Eigen::Ref<const Eigen::VectorXd>& time,
                                      const Eigen::Ref<const Eigen::VectorXd>& acceleration,
                                      const std::vector<double>& frequencies_hz, double damping_ratio) {
  return shock_response_spectra(time, acceleration, frequencies_hz, damping_ratio).front();
}

}  // namespace limber::results
