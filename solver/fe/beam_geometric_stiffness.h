// Geometric (initial-stress) stiffness of the 2-node 3D beam of beam_element.h under a
// constant axial force N [N] (tension > 0): the second-order work of N on the transverse
// displacements, ½ N ∫ (v'² + w'²) dx, plus the torsional term ½ N (Ip/A) ∫ θx'² dx.
//
// Local DOFs as beam_element.h (u v w θx θy θz per node, θz = +dv/dx, θy = −dw/dx):
//   K_G = N/L · [ 6/5    L/10     −6/5   L/10   ]  on (v0, θz0, v1, θz1), the same with the
//               [ L/10   2L²/15   −L/10  −L²/30 ]  signs of θy flipped on (w0, θy0, w1, θy1),
//               [ −6/5   −L/10    6/5    −L/10  ]
//               [ L/10   −L²/30   −L/10  2L²/15 ]
//         + N Ip/(A L) [1 −1; −1 1] on (θx0, θx1),  Ip = Iy + Iz.
// This is the consistent geometric stiffness of the cubic Hermite (Euler–Bernoulli)
// interpolation: Przemieniecki, "Theory of Matrix Structural Analysis" (1968), ch. 15;
// McGuire, Gallagher & Ziemian, "Matrix Structural Analysis", 2nd ed. (2000), eq. 9.17.
// Timoshenko elements use the same matrix (the shear correction of K_G is of order
// Φ = 12EI/(kGAL²), below 10⁻³ for the slender members it is meant for). Axial shortening
// terms (N/L on u) and bending-moment terms of K_G are left out, as in the references' beam–column
// form: this is the linearised-buckling geometric stiffness.
#pragma once

#include <Eigen/Core>

#include "fe/beam_element.h"
#include "fe/fe_model.h"

namespace limber::fe {

using Vector12d = Eigen::Matrix<double, 12, 1>;

// K_G in the local frame for an element of length `length` [m] (> 0, DEMAND) carrying the
// axial force `axial_force` [N].
Matrix12d beam_local_geometric_stiffness(double length, double axial_force, const BeamProperty& property);

// The same in global axes: Tᵀ K_G T with T = diag(R_LG ×4) (beam_element.h). Throws as
// beam_local_axes.
Matrix12d beam_geometric_stiffness(const Eigen::Vector3d& p_node0, const Eigen::Vector3d& p_node1,
                                   const Eigen::Vector3d& orientation, const BeamProperty& property,
                                   double axial_force);

// Axial force N = EA/L · x·(u1 − u0) [N] of the element under the global nodal displacements
// `u_global` (12, beam_element.h order), x the unit axis from node 0 to node 1.
double beam_axial_force(const Eigen::Vector3d& p_node0, const Eigen::Vector3d& p_node1,
                        const BeamProperty& property, const Vector12d& u_global);

}  // namespace limber::fe
