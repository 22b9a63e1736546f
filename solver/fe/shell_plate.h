// Plate-bending part of the flat 4-node shell (shell_element.h): the MITC4 Reissner–Mindlin
// quadrilateral, in the element's local frame.
//
// Kinematics (rotation vector θ, right-handed about local x, y): in-plane displacement at
// height z is z (θy, −θx); curvatures κ = (∂θy/∂x, −∂θx/∂y, ∂θy/∂y − ∂θx/∂x); transverse
// shear γ = (∂w/∂x + θy, ∂w/∂y − θx). w, θx, θy bilinear.
// Shear locking is removed by the assumed covariant transverse shear strains of Dvorkin &
// Bathe 1984 (Eng. Comput. 1:77) / Bathe & Dvorkin 1985 (IJNME 21:367): γ_ξ is interpolated
// linearly in η between the edge midpoints (0, ∓1), γ_η linearly in ξ between (∓1, 0), and
// (γxz, γyz) = J⁻¹ (γ_ξ, γ_η). Bending and shear use 2×2 Gauss integration.
//
// Local DOF order of the 12-vectors: node-major, per node (w, θx, θy).
#pragma once

#include <Eigen/Core>

#include "fe/fe_model.h"
#include "fe/shell_quad.h"

namespace limber::fe {

using Matrix12d = Eigen::Matrix<double, 12, 12>;
using Vector12d = Eigen::Matrix<double, 12, 1>;

// Bending + assumed-shear stiffness [N/m, N, N·m], with the section's bending rigidity
// (plate_bending_rigidity) and shear stiffness G shear_ratio T [N/m]; null space: the 3 plate
// rigid motions (w, θx, θy) = (1, 0, 0), (y, 1, 0), (−x, 0, 1). Precondition: a valid
// (convex) quad.
Matrix12d plate_stiffness(const QuadCoordinates& xy, const ShellProperty& property);

// Curvatures (κxx, κyy, κxy) [1/m] at (ξ, η) for nodal values `dofs` (w [m], θ [rad]).
Eigen::Vector3d plate_curvature(const QuadCoordinates& xy, const Vector12d& dofs, double xi,
                                double eta);

// MITC4 assumed transverse shear strains (γxz, γyz) at (ξ, η).
Eigen::Vector2d plate_shear_strain(const QuadCoordinates& xy, const Vector12d& dofs, double xi,
                                   double eta);

// Bending rigidity E I / (1 − ν²) [[1, ν, 0], [ν, 1, 0], [0, 0, (1 − ν)/2]] [N·m] with
// I = bending_ratio T³ / 12 [m³] (PSHELL 12I/T³); maps κ to the moments (Mxx, Myy, Mxy)
// per unit length.
Eigen::Matrix3d plate_bending_rigidity(const ShellProperty& property);

}  // namespace limber::fe
