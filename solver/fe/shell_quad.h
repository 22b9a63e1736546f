// Bilinear 4-node quadrilateral in the element's local plane: shape functions, their
// Cartesian derivatives, the Jacobian and the 2×2 Gauss rule. Shared by the membrane,
// plate and mass parts of the flat shell (shell_element.h).
//
// Node order and natural coordinates: node k sits at (ξ_k, η_k) = (-1,-1), (1,-1), (1,1),
// (-1,1); N_k = ¼(1 + ξ_k ξ)(1 + η_k η) (e.g. Zienkiewicz & Taylor, The Finite Element
// Method, vol. 1, §6).
#pragma once

#include <array>

#include <Eigen/Core>

namespace limber::fe {

// Corner coordinates (x, y) in the element's local plane [m], counter-clockwise.
using QuadCoordinates = std::array<Eigen::Vector2d, 4>;

inline constexpr std::array<double, 4> kCornerXi{-1.0, 1.0, 1.0, -1.0};
inline constexpr std::array<double, 4> kCornerEta{-1.0, -1.0, 1.0, 1.0};

// Everything an integrand needs at one point (ξ, η) of the quad.
struct QuadPoint {
  Eigen::Vector4d n;                    // N_k
  Eigen::Matrix<double, 2, 4> dn_dnat;  // rows ∂N_k/∂ξ, ∂N_k/∂η
  Eigen::Matrix<double, 2, 4> dn_dxy;   // rows ∂N_k/∂x, ∂N_k/∂y [1/m]
  Eigen::Matrix2d jacobian;             // [[x,ξ  y,ξ], [x,η  y,η]] [m]
  double det_j = 0.0;                   // det(jacobian) [m^2], > 0 for a valid quad
};

// Evaluates the bilinear map at (ξ, η). Precondition: det J > 0 there (checked by the
// frame construction in shell_frame.h, which rejects non-convex quads).
QuadPoint quad_point(const QuadCoordinates& xy, double xi, double eta);

// 2×2 Gauss–Legendre points ±1/√3, unit weights: exact for polynomials of degree 3 in
// each of ξ and η.
struct GaussPoint {
  double xi;
  double eta;
  double weight;
};
inline constexpr double kGaussAbscissa = 0.57735026918962576451;  // 1/√3
inline constexpr std::array<GaussPoint, 4> kGauss2x2{{{-kGaussAbscissa, -kGaussAbscissa, 1.0},
                                                      {kGaussAbscissa, -kGaussAbscissa, 1.0},
                                                      {kGaussAbscissa, kGaussAbscissa, 1.0},
                                                      {-kGaussAbscissa, kGaussAbscissa, 1.0}}};

}  // namespace limber::fe
