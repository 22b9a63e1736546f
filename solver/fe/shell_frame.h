// Local frame of a flat 4-node shell element (shell_element.h) and the checks on its shape.
//
// The element lies in the quad's mean plane: normal e3 = (x3 − x1) × (x4 − x2) / |…| (the
// diagonals' cross product, so the node order fixes the normal), origin at the corners'
// centroid, e1 along the projection of the mean ξ-direction (x2 + x3 − x1 − x4), e2 = e3 × e1.
// A warped quad is projected onto that plane; corner k then sits at a distance h_k from its
// projection (h alternates in sign: +h, −h, +h, −h) and shell_element.cpp joins both points
// rigidly, which keeps rigid motions exact (the rigid-link warp correction discussed
// for warped quadrilaterals in MacNeal, Finite Elements: Their Design and Performance, 1994).
#pragma once

#include <array>

#include <Eigen/Core>

#include "fe/shell_quad.h"

namespace limber::fe {

// Warp limit: max |h_k| / sqrt(projected area) ≤ 0.05. The flat element ignores the
// curvature implied by the warp; 0.05 (a 1 m quad whose corners sit ±5 cm off its mean plane)
// is the order of the default warp tolerance of common commercial geometry checks. Quads cut
// from a cylinder along generators and circles are flat (warp 0); twisted surfaces need a mesh
// fine enough to stay under the limit.
inline constexpr double kMaxShellWarpRatio = 0.05;

// Minimum corner Jacobian, relative to the mean: (edge_out × edge_in)_k / area ≥ 0.01.
// 1 for a parallelogram; 0 at a corner angle of 180° (non-convex limit) or at a collapsed
// edge (degenerate quad).
inline constexpr double kMinShellCornerRatio = 0.01;

struct ShellFrame {
  Eigen::Matrix3d rotation_WL;           // columns e1, e2, e3 in global components
  Eigen::Vector3d centroid_W;            // origin of the local frame [m]
  QuadCoordinates xy;                    // projected corners in (e1, e2) [m]
  std::array<double, 4> warp_offsets{};  // h_k = (x_k − centroid)·e3 [m]
  double area = 0.0;                     // projected area [m^2]
};

// Builds the frame of the quad `corners` (global positions [m], counter-clockwise about the
// intended normal). Throws InputError (expected/got message) when a diagonal has zero length
// or the diagonals are parallel (degenerate quad), when the warp exceeds kMaxShellWarpRatio,
// or when a corner ratio is below kMinShellCornerRatio (non-convex, crossed or collapsed quad).
ShellFrame shell_frame(const std::array<Eigen::Vector3d, 4>& corners);

}  // namespace limber::fe
