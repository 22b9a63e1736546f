// Rotations on the Lie group SO(3) for the co-rotational beam (corotational_beam.h).
//
// Rotations are rotation matrices (or unit quaternions in BeamState) composed multiplicatively;
// a rotation vector theta (axis times angle [rad]) appears only as the exponential coordinate of
// a rotation that stays small or local (an increment, or an element's rotation relative to its
// chord frame), never as a state summed additively.
//
// Conventions: S(a) b = a × b; exp(theta) = exp(S(theta)) (Rodrigues); spatial (left) spin
// delta_w: delta R = S(delta_w) R. Sources: Argyris, "An excursion into large rotations",
// CMAME 32 (1982); Battini & Pacoste, CMAME 191 (2002) 1755-1789, eqs. for T_s^-1 and K_h.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace limber::nonlinear_beam {

// S(a), the skew matrix with S(a) b = a × b.
Eigen::Matrix3d skew(const Eigen::Vector3d& a);

// exp(S(theta)) by Rodrigues' formula; exact for any angle.
Eigen::Matrix3d exp_so3(const Eigen::Vector3d& theta);
// The unit quaternion of exp(S(theta)).
Eigen::Quaterniond exp_quaternion(const Eigen::Vector3d& theta);

// The rotation vector theta of `rotation` with |theta| <= pi (principal logarithm), through the
// quaternion (accurate near 0 and up to pi). Precondition: `rotation` is orthonormal.
Eigen::Vector3d log_so3(const Eigen::Matrix3d& rotation);

// Inverse of the left Jacobian of exp, T_s^-1(theta): delta_theta = T_s^-1(theta) delta_w for
// a spatial spin delta_w of exp(theta). T_s^-1 = I - S/2 + beta(|theta|) S^2 with
// beta = (1 - (t/2) cot(t/2)) / t^2 (Taylor series below t = 0.05). Valid for |theta| < 2 pi.
Eigen::Matrix3d inverse_left_jacobian(const Eigen::Vector3d& theta);

// d(T_s^-T(theta) m)/d theta · T_s^-1(theta): the stiffness term of a moment m conjugate to
// theta when it is re-expressed on spins (Battini & Pacoste 2002, K_h).
Eigen::Matrix3d moment_rotation_stiffness(const Eigen::Vector3d& theta, const Eigen::Vector3d& m);

}  // namespace limber::nonlinear_beam
