#include "nonlinear_beam/rotation.h"

#include <cmath>

namespace limber::nonlinear_beam {

namespace {

// Below this angle beta and beta'/t come from their Taylor series: the closed forms lose
// digits to cancellation (1 - (t/2) cot(t/2) ~ t^2 / 12).
constexpr double kSeriesAngle = 0.05;

// beta(t) = (1 - a(t)) / t^2 with a(t) = (t/2) cot(t/2), and beta'(t) / t.
struct Beta {
  double value;
  double derivative_over_t;
};

Beta beta_of(double t) {
  if (t < kSeriesAngle) {
    // a(t) = 1 - t^2/12 - t^4/720 - t^6/30240 - t^8/1209600 - ...
    const double t2 = t * t;
    return {1.0 / 12.0 + t2 / 720.0 + t2 * t2 / 30240.0 + t2 * t2 * t2 / 1209600.0,
            2.0 / 720.0 + 4.0 * t2 / 30240.0 + 6.0 * t2 * t2 / 1209600.0};
  }
  const double half = 0.5 * t;
  const double a = half / std::tan(half);
  const double s = std::sin(half);
  // a'(t) = cot(t/2)/2 - t / (4 sin^2(t/2))
  const double a_prime = 0.5 / std::tan(half) - t / (4.0 * s * s);
  const double beta = (1.0 - a) / (t * t);
  const double beta_prime = -a_prime / (t * t) - 2.0 * (1.0 - a) / (t * t * t);
  return {beta, beta_prime / t};
}

}  // namespace

Eigen::Matrix3d skew(const Eigen::Vector3d& a) {
  Eigen::Matrix3d s;
  // clang-format off
  s << 0.0, -a.z(), a.y(),
       a.z(), 0.0, -a.x(),
       -a.y(), a.x(), 0.0;
  // clang-format on
  return s;
}

Eigen::Matrix3d exp_so3(const Eigen::Vector3d& theta) {
  return exp_quaternion(theta).toRotationMatrix();
}

Eigen::Quaterniond exp_quaternion(const Eigen::Vector3d& theta) {
  const double t = theta.norm();
  // sin(t/2)/t by its series near 0.
  const double c = t < 1e-4 ? 0.5 - t * t / 48.0 : std::sin(0.5 * t) / t;
  Eigen::Quaterniond q;
  q.w() = std::cos(0.5 * t);
  q.vec() = c * theta;
  return q;
}

Eigen::Vector3d log_so3(const Eigen::Matrix3d& rotation) {
  Eigen::Quaterniond q(rotation);
  // Principal branch: w >= 0 gives |theta| <= pi.
  if (q.w() < 0.0) q.coeffs() = -q.coeffs();
  const double s = q.vec().norm();
  const double t = 2.0 * std::atan2(s, q.w());
  // theta = t / sin(t/2) * vec; t / sin(t/2) -> 2 (1 + t^2/24) near 0.
  const double factor = s < 1e-8 ? 2.0 / q.w() : t / s;
  return factor * q.vec();
}

Eigen::Matrix3d inverse_left_jacobian(const Eigen::Vector3d& theta) {
  const Eigen::Matrix3d s = skew(theta);
  return Eigen::Matrix3d::Identity() - 0.5 * s + beta_of(theta.norm()).value * s * s;
}

Eigen::Matrix3d moment_rotation_stiffness(const Eigen::Vector3d& theta, const Eigen::Vector3d& m) {
  // g(theta) = T_s^-T m = m + theta × m / 2 + beta theta × (theta × m).
  const Beta beta = beta_of(theta.norm());
  const Eigen::Vector3d double_cross = theta * theta.dot(m) - m * theta.squaredNorm();
  Eigen::Matrix3d dg = -0.5 * skew(m);
  dg += beta.value * (theta.dot(m) * Eigen::Matrix3d::Identity() + theta * m.transpose() -
                      2.0 * m * theta.transpose());
  dg += beta.derivative_over_t * double_cross * theta.transpose();
  return dg * inverse_left_jacobian(theta);
}

}  // namespace limber::nonlinear_beam
