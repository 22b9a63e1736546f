// Two-node 3D beam element: 12x12 stiffness and consistent mass in global axes.
//
// DOF order: node-major, (ux uy uz rx ry rz) of node 0 then of node 1, the same order as
// FeModel (fe_model.h). Rotations are right-handed small rotations about the axes.
//
// Local frame (beam_local_axes): x from node 0 to node 1, z = x × orientation (normalised),
// y = z × x. Bending in the local x-y plane uses Iz (deflection v, rotation rz = +dv/dx);
// bending in the local x-z plane uses Iy (deflection w, rotation ry = -dw/dx).
//
// Formulation (J.S. Przemieniecki, "Theory of Matrix Structural Analysis", McGraw-Hill 1968,
// ch. 5 stiffness and ch. 11 inertia properties of beam elements; the Euler-Bernoulli limit is
// also in Cook, Malkus, Plesha & Witt, "Concepts and Applications of Finite Element Analysis"):
//  - axial: EA/L, linear consistent mass rho A L/6 [2 1; 1 2];
//  - St-Venant torsion: GJ/L, mass rho Ip L/6 [2 1; 1 2] with Ip = Iy + Iz;
//  - bending: cubic Hermite (Euler-Bernoulli), or with Timoshenko shear deformation through
//    Phi = 12 E I / (k G A L^2) in the stiffness, and the matching consistent mass (translational
//    and rotary-inertia rho I parts, each a quadratic in Phi over (1 + Phi)^2).
// With Phi = 0 the matrices are the classic Euler-Bernoulli ones; the rho I (rotary inertia)
// part of the bending mass is dropped when BeamProperty::rotary_inertia is false.
#pragma once

#include <Eigen/Core>

#include "fe/fe_model.h"

namespace limber::fe {

using Matrix12d = Eigen::Matrix<double, 12, 12>;

struct BeamElementMatrices {
  Matrix12d stiffness;  // K [N/m, N, N·m] (blocks by DOF kind)
  Matrix12d mass;       // consistent M [kg, kg·m, kg·m^2]
};

// Rotation R_LG whose rows are the local axes x, y, z in global components
// (v_local = R_LG v_global). Throws InputError when the nodes coincide or when
// `orientation` is (nearly, sine of the angle < 1e-6) parallel to the beam axis or zero.
Eigen::Matrix3d beam_local_axes(const Eigen::Vector3d& p_node0, const Eigen::Vector3d& p_node1,
                                const Eigen::Vector3d& orientation);

// Matrices in the local frame for a beam of length `length` [m] (> 0, checked by LIMBER_DEMAND).
BeamElementMatrices beam_local_matrices(double length, const BeamProperty& property);

// Matrices in global axes: T^T K_local T with T = diag(R_LG, R_LG, R_LG, R_LG).
// Throws as beam_local_axes.
BeamElementMatrices beam_element_matrices(const Eigen::Vector3d& p_node0,
                                          const Eigen::Vector3d& p_node1,
                                          const Eigen::Vector3d& orientation,
                                          const BeamProperty& property);

}  // namespace limber::fe
