// Membrane geometric (initial-stress) stiffness of the flat 4-node shell (shell_element.h)
// under the membrane forces of a given displacement: the second-order work of the in-plane
// forces N = (Nxx, Nyy, Nxy) [N/m] on the transverse deflection w,
//   ½ ∫ [w,x  w,y] [Nxx Nxy; Nxy Nyy] [w,x  w,y]ᵀ dA,
// with w bilinear in the corners' local-z translations and N from membrane_strain and
// membrane_elasticity (shell_membrane.h) at each point of the 2×2 Gauss rule — the plate
// buckling geometric stiffness of e.g. Cook, Malkus, Plesha & Witt, "Concepts and Applications
// of Finite Element Analysis", 4th ed., 2002, §18.5 (bilinear interpolation of w, as is common
// for the geometric stiffness of 4-node shells). In-plane displacement terms of the
// initial-stress matrix are left out (linearised buckling form), and the element is taken flat
// (the warp offsets of shell_frame.h are ignored here).
#pragma once

#include <array>

#include <Eigen/Core>

#include "fe/fe_model.h"

namespace limber::fe {

using Matrix24d = Eigen::Matrix<double, 24, 24>;
using Vector24d = Eigen::Matrix<double, 24, 1>;

// K_G (24 x 24, global axes, DOFs as shell_element.h: node-major ux uy uz rx ry rz) for the
// corners `corners` [m] under the global nodal displacements `u_global` [m, rad]. Throws as
// shell_frame for a degenerate or warped quad.
Matrix24d shell_geometric_stiffness(const std::array<Eigen::Vector3d, 4>& corners, const ShellProperty& property,
                                    const Vector24d& u_global);

}  // namespace limber::fe
