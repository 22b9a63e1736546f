// Membrane part of the flat 4-node shell (shell_element.h), in the element's local frame.
//
// Plane stress, bilinear displacements enriched with the two incompatible modes 1 − ξ² and
// 1 − η² per direction (Wilson, Taylor, Doherty & Ghaboussi 1973, "Incompatible displacement
// models"), whose derivatives use the centre Jacobian scaled by det J0 / det J so that they
// integrate to zero and the element passes the patch test (Taylor, Beresford & Wilson 1976,
// IJNME 10:1211, "QM6"). The 4 modes are condensed statically. 2×2 Gauss integration.
//
// Drilling rotation θz: penalty α G t ∫ (θz − ω)² dA with ω = ½(∂v/∂x − ∂u/∂y) of the whole
// membrane field (bilinear + incompatible modes, condensed together) and θz bilinear in its
// nodal values, 2×2 Gauss (the drilling functional of Hughes & Brezzi 1989, CMAME 72:105,
// used with a small α as stabilisation only). Rigid in-plane rotation, every linear field and,
// on a rectangle, pure in-plane bending carry no drilling energy when θz = ω at the nodes.
//
// Local DOF order of the 12×12 results: node-major, per node (u, v, θz).
#pragma once

#include <Eigen/Core>

#include "fe/fe_model.h"
#include "fe/shell_quad.h"

namespace limber::fe {

// α in the drilling penalty above. Measured on a 10 × 2 in-plane cantilever under tip shear,
// going from α = 1e-6 to 1e-3 changes the tip deflection by 7e-8 (rectangles) and 1e-5
// (strongly distorted quads); the drilling eigenvalues stay ~1e-3 G t A, well clear of zero.
// The patch tests, rigid motions and pure in-plane bending are independent of α.
inline constexpr double kDrillingPenalty = 1e-3;

using Matrix12d = Eigen::Matrix<double, 12, 12>;
using Vector12d = Eigen::Matrix<double, 12, 1>;

// Membrane + drilling stiffness [N/m, N, N·m], symmetric positive semi-definite with the
// 3 in-plane rigid motions as its null space. Precondition: a valid (convex) quad.
Matrix12d membrane_stiffness(const QuadCoordinates& xy, const ShellProperty& property);

// In-plane strain (εxx, εyy, γxy) at (ξ, η) for local nodal DOFs
// dofs = (u1, v1, θz1, u2, …) [m, rad], with the incompatible modes recovered from their
// condensation (they vanish for a linear field).
Eigen::Vector3d membrane_strain(const QuadCoordinates& xy, const ShellProperty& property,
                                const Vector12d& dofs, double xi, double eta);

// Plane-stress elasticity times thickness, E t / (1 − ν²) [[1, ν, 0], [ν, 1, 0],
// [0, 0, (1 − ν)/2]] [N/m]; maps (εxx, εyy, γxy) to membrane forces (Nxx, Nyy, Nxy).
Eigen::Matrix3d membrane_elasticity(const ShellProperty& property);

}  // namespace limber::fe
