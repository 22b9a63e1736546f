// Flat 3-node thin-shell triangle, 6 DOFs per node (ux, uy, uz, rx, ry, rz, global axes), for
// triangular meshes (NASTRAN CTRIA3): docs/shell-element.md, "The triangle".
//
// In the triangle's plane (local x along node 1 → 2, z the normal (x2 − x1) × (x3 − x1)):
//  - membrane: the constant-strain triangle (CST; Turner, Clough, Martin & Topp 1956), plane
//    stress E T / (1 − ν²), exact for every linear displacement field;
//  - plate: the Discrete Kirchhoff Triangle (DKT) of Batoz, Bathe & Ho 1980 ("A study of
//    three-node triangular plate bending elements", IJNME 15:1771-1812), in Batoz's explicit
//    form: rotations βx, βy quadratic, with the Kirchhoff constraints imposed at the corners
//    and along the edges; bending rigidity E I / (1 − ν²), I = 12I/T³ · T³/12 (PSHELL). The DKT
//    is a thin-plate (Kirchhoff) element: PSHELL's TS/T has no effect on it. It passes the
//    constant-curvature patch test; 3-point rule exact for its stiffness;
//  - drilling: the Hughes–Brezzi penalty α G T ∫ (θz − ω)² dA with ω = ½(∂v/∂x − ∂u/∂y) of the
//    CST field, θz linear, α = kDrillingPenalty as for the quad (shell_membrane.h);
//  - mass: ρ T + NSM on (u, v, w) and ρ I on (θx, θy), ρ T³/12 on θz, with linear shape
//    functions (consistent for the CST; for the DKT's w, whose interior the element does not
//    define, the linear field is the usual choice), ∫ Li Lj dA = A (1 + δij) / 12.
// The local plate DOFs (w, θx, θy) are limber's: θx = ∂w/∂y, θy = −∂w/∂x (shell_plate.h).
#pragma once

#include <array>

#include <Eigen/Core>

#include "fe/fe_model.h"

namespace limber::fe {

// Shape check: 2 A / (longest edge)² ≥ 0.01 (0.866 for an equilateral triangle; 0.01 is a
// corner angle of about 0.6°, below which the element is a sliver).
inline constexpr double kMinTriangleShapeRatio = 0.01;

using Matrix18d = Eigen::Matrix<double, 18, 18>;
using Matrix9d = Eigen::Matrix<double, 9, 9>;

struct ShellTriangleMatrices {
  Matrix18d stiffness;  // [N/m, N, N·m] in global axes, node-major
  Matrix18d mass;       // [kg, kg·m, kg·m²]
};

// Node positions in the triangle's local frame (x, y) [m].
using TriangleCoordinates = std::array<Eigen::Vector2d, 3>;

// DKT plate stiffness, local DOFs node-major (w, θx, θy). Precondition: positive area.
Matrix9d dkt_stiffness(const TriangleCoordinates& xy, const ShellProperty& property);

// DKT curvatures (κxx, κyy, κxy) [1/m] at area coordinates (ξ, η) (node 1 at (0, 0), node 2
// at (1, 0), node 3 at (0, 1)) for local nodal values (w, θx, θy) node-major.
Eigen::Vector3d dkt_curvature(const TriangleCoordinates& xy, const Eigen::Matrix<double, 9, 1>& dofs,
                              double xi, double eta);

// CST membrane + drilling stiffness, local DOFs node-major (u, v, θz).
Matrix9d cst_stiffness(const TriangleCoordinates& xy, const ShellProperty& property);

// Element matrices of the triangle `corners` [m] (normal by the node order). Throws
// InputError when the triangle is degenerate (shape ratio below kMinTriangleShapeRatio).
ShellTriangleMatrices shell_triangle_matrices(const std::array<Eigen::Vector3d, 3>& corners,
                                              const ShellProperty& property);

}  // namespace limber::fe
