// Flat 4-node thin-shell element, 6 DOFs per node (ux uy uz rx ry rz, global axes).
// Membrane and plate bending superposed in the element's local frame, with drilling
// stabilisation on the in-plane rotation; see shell_element.cpp for the formulation
// and its references.
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

// Element matrices of a quad with corner positions `corners` (counter-clockwise about
// the normal). Throws InputError when the quad is degenerate (zero area, a non-convex
// corner, or a warp too large for a flat element).
ShellElementMatrices shell_element_matrices(const std::array<Eigen::Vector3d, 4>& corners,
                                            const ShellProperty& property);

}  // namespace limber::fe
