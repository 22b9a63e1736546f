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

}  // namespace limber::fe
