// Flat 4-node thin-shell element, 6 DOFs per node (ux uy uz rx ry rz, global axes).
// Membrane (plane stress with incompatible modes, shell_membrane.h) and MITC4 plate bending
// (Dvorkin & Bathe 1984, shell_plate.h) superposed in the local frame of the quad's mean plane
// (shell_frame.h), with a Hughes–Brezzi drilling penalty on the in-plane rotation and a
// consistent mass (shell_element.cpp). Formulation, references and verification:
// docs/shell-element.md.
#pragma once

#include <array>

#include <Eigen/Core>

#include "fe/fe_model.h"
#include "fe/shell_frame.h"

namespace limber::fe {

using Matrix24d = Eigen::Matrix<double, 24, 24>;

struct ShellElementMatrices {
  Matrix24d stiffness;  // [N/m, N, N·m] in global axes, DOF order node-major
  Matrix24d mass;       // consistent mass [kg, kg·m, kg·m^2]
};

// Element matrices of a quad with corner positions `corners` [m] (counter-clockwise about
// the normal, which the node order defines). Precondition: thickness, E, bending_ratio and
// shear_ratio > 0, nonstructural_mass >= 0 (the builder checks them). Throws InputError when
// the quad is degenerate (zero area, a non-convex corner, or a warp beyond
// kMaxShellWarpRatio, see shell_frame.h).
ShellElementMatrices shell_element_matrices(const std::array<Eigen::Vector3d, 4>& corners,
                                            const ShellProperty& property);

// Local indices (within a node's 6) of the membrane (u, v, θz) and plate (w, θx, θy) DOFs.
inline constexpr std::array<int, 3> kShellMembraneDofs{0, 1, 5};
inline constexpr std::array<int, 3> kShellPlateDofs{2, 3, 4};

// Global-to-local map T (d_local = T d_global, 24 × 24): the rotation to the frame's local
// axes, preceded for a warped quad by the rigid offset from each corner to its projection on
// the mean plane, u_projected = u + θ × (−h_k e3).
Matrix24d shell_global_to_local(const ShellFrame& frame);

}  // namespace limber::fe
