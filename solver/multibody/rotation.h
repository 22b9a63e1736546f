// Rotation helpers for Euler parameters (unit quaternions p = (w, x, y, z)) and
// body-axis angular velocities (Nikravesh, Computer-Aided Analysis of Mechanical
// Systems, 1988, ch. 6; Haug, Computer-Aided Kinematics and Dynamics, 1989, §6.3):
//   A(p)     rotation matrix ground <- body,
//   ṗ = ½ L(p)ᵀ ω'   with ω' the angular velocity in body axes,   ω' = 2 L(p) ṗ,
//   L(p) = [−x⃗, w I − x̃⃗] (3 x 4),  L(p) L(p)ᵀ = |p|² I,  L(p) p = 0.
#pragma once

#include <Eigen/Dense>

namespace limber::multibody {

// Cross-product matrix: skew(a) b = a × b.
Eigen::Matrix3d skew(const Eigen::Vector3d& a);

// Rotation matrix of p/|p| (ground <- body). Precondition: |p| > 0.
Eigen::Matrix3d rotation_matrix(const Eigen::Vector4d& p);

// L(p), 3 x 4, as in the header comment (no normalisation).
Eigen::Matrix<double, 3, 4> l_matrix(const Eigen::Vector4d& p);

// Quaternion product a ⊗ b (Hamilton convention, scalar first).
Eigen::Vector4d quaternion_product(const Eigen::Vector4d& a, const Eigen::Vector4d& b);

// exp of a rotation vector θ (rad): the unit quaternion (cos|θ|/2, sin(|θ|/2) θ/|θ|).
Eigen::Vector4d quaternion_exp(const Eigen::Vector3d& theta);

// Unit quaternion of a rotation matrix (Shepperd's method, w ≥ 0).
Eigen::Vector4d quaternion_from_matrix(const Eigen::Matrix3d& R);

// Rotation of `angle` rad about the unit `axis`, as a matrix.
Eigen::Matrix3d axis_angle_matrix(const Eigen::Vector3d& axis, double angle);

// exp([θ]×), the rotation matrix of a rotation vector θ [rad] (θ = 0 gives I).
Eigen::Matrix3d rotation_vector_matrix(const Eigen::Vector3d& theta);

// Left Jacobian of SO(3): d/dt exp([θ]×) = [J_l(θ) θ̇]× exp([θ]×), so J_l θ̇ is the
// angular velocity (in the axes of the parent frame) of a frame turned by θ(t):
//   J_l = I + a(t) [θ]× + b(t) [θ]×²,  a = (1 − cos t)/t²,  b = (t − sin t)/t³,  t = |θ|
// (Chirikjian, Stochastic Models, Information Theory and Lie Groups, vol. 2, 2012, §10.2).
Eigen::Matrix3d so3_left_jacobian(const Eigen::Vector3d& theta);

// (d/dt J_l(θ)) θ̇ for the motion θ(t) with rate θ̇: the bias term of the angular
// acceleration J_l θ̈ + J̇_l θ̇.
Eigen::Vector3d so3_left_jacobian_rate(const Eigen::Vector3d& theta, const Eigen::Vector3d& theta_dot);

}  // namespace limber::multibody

namespace limber::multibody {

// An orthonormal right-handed frame (columns x, y, z) whose z axis is `z` (normalised) and
// whose x axis is the component of `x_hint` orthogonal to z. Throws InputError when z is
// zero or x_hint is parallel to z.
Eigen::Matrix3d frame_from_axes(const Eigen::Vector3d& z, const Eigen::Vector3d& x_hint);

// As above with x chosen automatically (the ground axis least aligned with z).
Eigen::Matrix3d frame_from_z_axis(const Eigen::Vector3d& z);

}  // namespace limber::multibody
