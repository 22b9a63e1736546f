#include "multibody/rotation.h"

#include <cmath>

#include <fmt/format.h>

#include "core/error.h"

namespace limber::multibody {

Eigen::Matrix3d skew(const Eigen::Vector3d& a) {
  Eigen::Matrix3d S;
  S << 0.0, -a.z(), a.y(), a.z(), 0.0, -a.x(), -a.y(), a.x(), 0.0;
  return S;
}

Eigen::Matrix3d rotation_matrix(const Eigen::Vector4d& p) {
  // Normalise, then A = (w² − x⃗ᵀx⃗) I + 2 x⃗x⃗ᵀ + 2 w x̃⃗.
  const Eigen::Vector4d u = p / p.norm();
  const double w = u(0);
  const Eigen::Vector3d x = u.tail<3>();
  return (w * w - x.squaredNorm()) * Eigen::Matrix3d::Identity() + 2.0 * x * x.transpose() +
         2.0 * w * skew(x);
}

Eigen::Matrix<double, 3, 4> l_matrix(const Eigen::Vector4d& p) {
  Eigen::Matrix<double, 3, 4> L;
  L.col(0) = -p.tail<3>();
  L.rightCols<3>() = p(0) * Eigen::Matrix3d::Identity() - skew(p.tail<3>());
  return L;
}

Eigen::Vector4d quaternion_product(const Eigen::Vector4d& a, const Eigen::Vector4d& b) {
  Eigen::Vector4d c;
  c(0) = a(0) * b(0) - a.tail<3>().dot(b.tail<3>());
  c.tail<3>() = a(0) * b.tail<3>() + b(0) * a.tail<3>() + a.tail<3>().cross(b.tail<3>());
  return c;
}

Eigen::Vector4d quaternion_exp(const Eigen::Vector3d& theta) {
  // Use the Taylor series of sin(x/2)/x below 1e-4 rad, where it is exact to rounding.
  const double angle = theta.norm();
  const double s = angle < 1e-4 ? 0.5 - angle * angle / 48.0 : std::sin(0.5 * angle) / angle;
  Eigen::Vector4d q;
  q << std::cos(0.5 * angle), s * theta;
  return q;
}

Eigen::Vector4d quaternion_from_matrix(const Eigen::Matrix3d& R) {
  // Pick the largest of 4w², 4x², 4y², 4z² as the pivot for accuracy.
  const double tr = R.trace();
  Eigen::Vector4d q;
  if (tr >= R(0, 0) && tr >= R(1, 1) && tr >= R(2, 2)) {
    const double w = 0.5 * std::sqrt(1.0 + tr);
    q << w, (R(2, 1) - R(1, 2)) / (4 * w), (R(0, 2) - R(2, 0)) / (4 * w),
        (R(1, 0) - R(0, 1)) / (4 * w);
  } else if (R(0, 0) >= R(1, 1) && R(0, 0) >= R(2, 2)) {
    const double x = 0.5 * std::sqrt(1.0 + 2 * R(0, 0) - tr);
    q << (R(2, 1) - R(1, 2)) / (4 * x), x, (R(0, 1) + R(1, 0)) / (4 * x),
        (R(0, 2) + R(2, 0)) / (4 * x);
  } else if (R(1, 1) >= R(2, 2)) {
    const double y = 0.5 * std::sqrt(1.0 + 2 * R(1, 1) - tr);
    q << (R(0, 2) - R(2, 0)) / (4 * y), (R(0, 1) + R(1, 0)) / (4 * y), y,
        (R(1, 2) + R(2, 1)) / (4 * y);
  } else {
    const double z = 0.5 * std::sqrt(1.0 + 2 * R(2, 2) - tr);
    q << (R(1, 0) - R(0, 1)) / (4 * z), (R(0, 2) + R(2, 0)) / (4 * z),
        (R(1, 2) + R(2, 1)) / (4 * z), z;
  }
  if (q(0) < 0) q = -q;
  return q / q.norm();
}

Eigen::Matrix3d axis_angle_matrix(const Eigen::Vector3d& axis, double angle) {
  return rotation_matrix(quaternion_exp(axis.normalized() * angle));
}

Eigen::Matrix3d rotation_vector_matrix(const Eigen::Vector3d& theta) {
  return rotation_matrix(quaternion_exp(theta));
}

namespace {

// Coefficients of J_l and their derivatives divided by t: a, b, a'(t)/t, b'(t)/t. Below
// t = 1e-2 the Taylor series (next terms ~ t⁶/10⁵ < 1e-16) avoid the cancellation of the
// closed forms.
struct LeftJacobianCoefficients {
  double a, b, a_rate, b_rate;
};

LeftJacobianCoefficients left_jacobian_coefficients(double t) {
  const double t2 = t * t;
  if (t < 1e-2) {
    const double t4 = t2 * t2;
    return {0.5 - t2 / 24.0 + t4 / 720.0, 1.0 / 6.0 - t2 / 120.0 + t4 / 5040.0,
            -1.0 / 12.0 + t2 / 180.0 - t4 / 6720.0, -1.0 / 60.0 + t2 / 1260.0 - t4 / 60480.0};
  }
  const double c = std::cos(t), s = std::sin(t);
  return {(1.0 - c) / t2, (t - s) / (t2 * t), (t * s - 2.0 * (1.0 - c)) / (t2 * t2),
          (t * (1.0 - c) - 3.0 * (t - s)) / (t2 * t2 * t)};
}

}  // namespace

Eigen::Matrix3d so3_left_jacobian(const Eigen::Vector3d& theta) {
  const LeftJacobianCoefficients k = left_jacobian_coefficients(theta.norm());
  const Eigen::Matrix3d S = skew(theta);
  return Eigen::Matrix3d::Identity() + k.a * S + k.b * S * S;
}

Eigen::Vector3d so3_left_jacobian_rate(const Eigen::Vector3d& theta, const Eigen::Vector3d& theta_dot) {
  // J̇_l θ̇ = ȧ θ×θ̇ + ḃ θ×(θ×θ̇) + b θ̇×(θ×θ̇), with ṫ = θ·θ̇/t.
  const LeftJacobianCoefficients k = left_jacobian_coefficients(theta.norm());
  const double projection = theta.dot(theta_dot);
  const Eigen::Vector3d c = theta.cross(theta_dot);
  return k.a_rate * projection * c + k.b_rate * projection * theta.cross(c) + k.b * theta_dot.cross(c);
}

Eigen::Matrix3d frame_from_axes(const Eigen::Vector3d& z, const Eigen::Vector3d& x_hint) {
  if (!(z.norm() > 0.0)) throw InputError("frame z axis: expected a non-zero vector, got zero");
  const Eigen::Vector3d ez = z.normalized();
  const Eigen::Vector3d x = x_hint - x_hint.dot(ez) * ez;
  if (!(x.norm() > 1e-9 * x_hint.norm())) {
    throw InputError(fmt::format("frame x axis: expected a vector not parallel to z = ({}, {}, {})",
                                 ez.x(), ez.y(), ez.z()));
  }
  Eigen::Matrix3d R;
  R.col(0) = x.normalized();
  R.col(2) = ez;
  R.col(1) = ez.cross(R.col(0));
  return R;
}

Eigen::Matrix3d frame_from_z_axis(const Eigen::Vector3d& z) {
  // The ground axis least aligned with z makes the best x hint.
  Eigen::Index k = 0;
  z.cwiseAbs().minCoeff(&k);
  return frame_from_axes(z, Eigen::Vector3d::Unit(k));
}

}  // namespace limber::multibody
