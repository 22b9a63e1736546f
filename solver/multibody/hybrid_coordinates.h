// Flexible-spacecraft data of a linearized mechanism (docs/linearize.md), in the hybrid
// coordinates of Likins (1967, "Modal analysis of structures as an aid to the attitude control
// of spacecraft", and Hughes, Spacecraft Attitude Dynamics, ch. 10): the reference body's
// rigid motion about a point P (the whole mechanism following it rigidly, joints locked at
// their current angles) and the motions with the reference body held ("cantilevered"):
//   Ψ (nv x 6): the whole-mechanism rigid motions, columns translation x, y, z (ground axes) and
//               small rotation about x, y, z through P: per body ṙ = u + θ × (r − P), ω_B = R_WBᵀ θ,
//               η̇ = 0;
//   M_rr = Ψᵀ M Ψ: mass properties of the whole mechanism about P [kg, kg m, kg m²];
//   Φ: cantilevered normal modes, Φᵀ M Φ = I;
//   L = Φᵀ M Ψ (n x 6): the modal participation factors [kg^½, kg^½ m]: translational coupling
//       matrix L(:, 0:3)ᵀ (3 x n), rotational L(:, 3:6)ᵀ (3 x n);
//   effective masses L(i, d)² [kg, kg m²] per mode and direction T1–T3, R1–R3 (Craig & Bampton
//   1968; Craig & Kurdila, Fundamentals of Structural Dynamics, §17.6).
// Completeness: Σ_i Lᵢᵀ Lᵢ = Ψᵀ M P_c Ψ with P_c the M-orthogonal projector onto the held
// motions; it equals the appendages' own rigid mass about P when they are attached to the
// reference body by force elements only (then every appendage motion is a held motion); joints
// to the reference body leave a residual mass, reported.
#pragma once

#include <Eigen/Core>

#include "multibody/linearization.h"
#include "multibody/model.h"
#include "multibody/state.h"

namespace limber::multibody {

// Ψ above, about point P (ground axes) at `state`.
Eigen::MatrixXd rigid_motion_basis(const Model& model, const State& state, const Eigen::Vector3d& p_WP);

struct MassProperties {
  double mass = 0.0;                                   // [kg]
  Eigen::Vector3d com_W = Eigen::Vector3d::Zero();     // centre of mass, ground axes [m]
  Eigen::Matrix3d inertia_com_W = Eigen::Matrix3d::Zero();  // about the CoM, ground axes [kg m²]
};

// Mass, centre of mass and inertia about it of the bodies whose velocity blocks Ψ spans,
// from Ψᵀ M Ψ about p_WP (exact for flexible bodies in their current deformation).
MassProperties mass_properties(const Eigen::MatrixXd& rigid_mass_P, const Eigen::Vector3d& p_WP);

struct CantileveredModes {
  int reference_body = 0;
  Eigen::Vector3d p_WP = Eigen::Vector3d::Zero();  // the reference point: the body's centre of mass
  SystemModes modes;                              // with the reference body held
  Eigen::MatrixXd participation;                  // L, n x 6 (zero-frequency held modes included)
  Eigen::MatrixXd effective_mass;                 // n x 6: L² [kg; kg m²]
  Eigen::Matrix<double, 6, 6> rigid_mass;         // M_rr of the whole mechanism about P
  Eigen::Matrix<double, 6, 6> appendage_mass;     // Ψ_aᵀ M Ψ_a: everything but the reference body
  Eigen::Matrix<double, 6, 1> effective_sum;      // Σ_i L(i, d)²
  double largest_constraint_rate = 0.0;           // max |G_i Ψ| / |Ψ|: ≈ 0 when free-floating
};

// The modes with body `reference_body` held (its 6 frame velocities appended to the rows of
// `tangent`), their coupling to Ψ about the body's centre of mass and their effective masses.
// Precondition (DEMAND): reference_body indexes a moving body (the command checks the name
// first, as bad input). Throws NumericalError as system_modes does.
CantileveredModes cantilevered_modes(const Model& model, const State& state, const TangentMatrices& tangent,
                                     int reference_body, double zero_threshold_hz = 0.0);

}  // namespace limber::multibody
