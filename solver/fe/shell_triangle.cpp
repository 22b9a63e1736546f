#include "fe/shell_triangle.h"

#include <fmt/format.h>

#include <Eigen/Geometry>
#include <algorithm>

#include "core/error.h"
#include "fe/shell_membrane.h"
#include "fe/shell_plate.h"

namespace limber::fe {

namespace {

using Vector9d = Eigen::Matrix<double, 9, 1>;
using Vector6d = Eigen::Matrix<double, 6, 1>;

// Local indices (within a node's 6) of the membrane (u, v, θz) and plate (w, θx, θy) DOFs.
constexpr std::array<int, 3> kMembraneDofs{0, 1, 5};
constexpr std::array<int, 3> kPlateDofs{2, 3, 4};

// The midside points of the triangle: the 3-point rule, exact for quadratics (weights 1/3).
constexpr std::array<std::array<double, 2>, 3> kMidsides{{{0.5, 0.0}, {0.5, 0.5}, {0.0, 0.5}}};

// Twice the signed area, from the local coordinates.
double twice_area(const TriangleCoordinates& xy) {
  return (xy[1].x() - xy[0].x()) * (xy[2].y() - xy[0].y()) -
         (xy[2].x() - xy[0].x()) * (xy[1].y() - xy[0].y());
}

// Batoz's edge coefficients a, b, c, d, e of edges 4 (nodes 2-3), 5 (3-1), 6 (1-2).
struct EdgeCoefficients {
  std::array<double, 3> a, b, c, d, e;  // index 0: edge 4, 1: edge 5, 2: edge 6
};

EdgeCoefficients edge_coefficients(const TriangleCoordinates& xy) {
  constexpr std::array<std::array<int, 2>, 3> kEdges{{{1, 2}, {2, 0}, {0, 1}}};
  EdgeCoefficients k;
  for (int m = 0; m < 3; ++m) {
    const double x = xy[kEdges[m][0]].x() - xy[kEdges[m][1]].x();
    const double y = xy[kEdges[m][0]].y() - xy[kEdges[m][1]].y();
    const double l2 = x * x + y * y;
    k.a[m] = -x / l2;
    k.b[m] = 0.75 * x * y / l2;
    k.c[m] = (0.25 * x * x - 0.5 * y * y) / l2;
    k.d[m] = -y / l2;
    k.e[m] = (0.25 * y * y - 0.5 * x * x) / l2;
  }
  return k;
}

// Batoz's Hx, Hy (βx = Hxᵀ U, βy = Hyᵀ U) from the six quadratic functions N1..N6 or from
// their derivatives (the map is linear in them).
void batoz_h(const EdgeCoefficients& k, const Vector6d& n, Vector9d& hx, Vector9d& hy) {
  const auto& [a, b, c, d, e] = k;
  // Edge m (0: 4, 1: 5, 2: 6) has function n(3 + m); its nodes follow.
  const double n4 = n(3), n5 = n(4), n6 = n(5);
  hx << 1.5 * (a[2] * n6 - a[1] * n5), b[1] * n5 + b[2] * n6, n(0) - c[1] * n5 - c[2] * n6,
      1.5 * (a[0] * n4 - a[2] * n6), b[2] * n6 + b[0] * n4, n(1) - c[2] * n6 - c[0] * n4,
      1.5 * (a[1] * n5 - a[0] * n4), b[0] * n4 + b[1] * n5, n(2) - c[0] * n4 - c[1] * n5;
  hy << 1.5 * (d[2] * n6 - d[1] * n5), -n(0) + e[1] * n5 + e[2] * n6, -b[1] * n5 - b[2] * n6,
      1.5 * (d[0] * n4 - d[2] * n6), -n(1) + e[2] * n6 + e[0] * n4, -b[2] * n6 - b[0] * n4,
      1.5 * (d[1] * n5 - d[0] * n4), -n(2) + e[0] * n4 + e[1] * n5, -b[0] * n4 - b[1] * n5;
}

// Curvature matrix B (κ = B U) of the DKT at (ξ, η).
Eigen::Matrix<double, 3, 9> dkt_b(const TriangleCoordinates& xy, double xi, double eta) {
  const EdgeCoefficients k = edge_coefficients(xy);
  const double l = 1.0 - xi - eta;
  // dN/dξ and dN/dη of N1 = L(2L − 1), N2 = ξ(2ξ − 1), N3 = η(2η − 1), N4 = 4ξη, N5 = 4ηL,
  // N6 = 4ξL.
  Vector6d dn_dxi, dn_deta;
  dn_dxi << 1.0 - 4.0 * l, 4.0 * xi - 1.0, 0.0, 4.0 * eta, -4.0 * eta, 4.0 * l - 4.0 * xi;
  dn_deta << 1.0 - 4.0 * l, 0.0, 4.0 * eta - 1.0, 4.0 * xi, 4.0 * l - 4.0 * eta, -4.0 * xi;
  Vector9d hx_xi, hy_xi, hx_eta, hy_eta;
  batoz_h(k, dn_dxi, hx_xi, hy_xi);
  batoz_h(k, dn_deta, hx_eta, hy_eta);

  // ∂/∂x = (y31 ∂/∂ξ + y12 ∂/∂η) / 2A, ∂/∂y = (−x31 ∂/∂ξ − x12 ∂/∂η) / 2A.
  const double x31 = xy[2].x() - xy[0].x(), y31 = xy[2].y() - xy[0].y();
  const double x12 = xy[0].x() - xy[1].x(), y12 = xy[0].y() - xy[1].y();
  const double two_a = twice_area(xy);
  Eigen::Matrix<double, 3, 9> b;
  b.row(0) = (y31 * hx_xi + y12 * hx_eta).transpose();
  b.row(1) = (-x31 * hy_xi - x12 * hy_eta).transpose();
  b.row(2) = (-x31 * hx_xi - x12 * hx_eta + y31 * hy_xi + y12 * hy_eta).transpose();
  return b / two_a;
}

// Adds a 9×9 matrix laid out as 3 nodes × 3 DOFs into the 18×18 local matrix.
void scatter(const Matrix9d& part, const std::array<int, 3>& dofs, Matrix18d& whole) {
  for (int a = 0; a < 3; ++a) {
    for (int i = 0; i < 3; ++i) {
      for (int b = 0; b < 3; ++b) {
        for (int j = 0; j < 3; ++j) whole(6 * a + dofs[i], 6 * b + dofs[j]) += part(3 * a + i, 3 * b + j);
      }
    }
  }
}

// Mass in the local frame: linear shape functions, ∫ Li Lj dA = A (1 + δij) / 12.
Matrix18d local_mass(double area, const ShellProperty& property) {
  const double t = property.thickness;
  const double rho = property.material.density;
  const double translational = rho * t + property.nonstructural_mass;
  const double rotary = rho * property.bending_ratio * t * t * t / 12.0;
  const double drilling = rho * t * t * t / 12.0;
  Matrix18d m = Matrix18d::Zero();
  for (int a = 0; a < 3; ++a) {
    for (int b = 0; b < 3; ++b) {
      const double nn = area * (a == b ? 2.0 : 1.0) / 12.0;
      for (int i = 0; i < 3; ++i) m(6 * a + i, 6 * b + i) = translational * nn;
      for (int i = 3; i < 5; ++i) m(6 * a + i, 6 * b + i) = rotary * nn;
      m(6 * a + 5, 6 * b + 5) = drilling * nn;
    }
  }
  return m;
}

}  // namespace

Eigen::Vector3d dkt_curvature(const TriangleCoordinates& xy, const Eigen::Matrix<double, 9, 1>& dofs,
                              double xi, double eta) {
  return dkt_b(xy, xi, eta) * dofs;
}

Matrix9d dkt_stiffness(const TriangleCoordinates& xy, const ShellProperty& property) {
  const Eigen::Matrix3d d = plate_bending_rigidity(property);
  const double area = 0.5 * twice_area(xy);
  Matrix9d k = Matrix9d::Zero();
  for (const auto& [xi, eta] : kMidsides) {
    const Eigen::Matrix<double, 3, 9> b = dkt_b(xy, xi, eta);
    k += (area / 3.0) * b.transpose() * d * b;
  }
  return 0.5 * (k + k.transpose());
}

Matrix9d cst_stiffness(const TriangleCoordinates& xy, const ShellProperty& property) {
  const double two_a = twice_area(xy);
  const double area = 0.5 * two_a;
  // b_i = y_j − y_k, c_i = x_k − x_j for (i, j, k) cyclic.
  std::array<double, 3> b{}, c{};
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3, k = (i + 2) % 3;
    b[i] = xy[j].y() - xy[k].y();
    c[i] = xy[k].x() - xy[j].x();
  }
  // Plane stress: ε = (εxx, εyy, γxy) = B (u, v, θz) node-major, constant.
  Eigen::Matrix<double, 3, 9> strain = Eigen::Matrix<double, 3, 9>::Zero();
  for (int i = 0; i < 3; ++i) {
    strain(0, 3 * i) = b[i] / two_a;
    strain(1, 3 * i + 1) = c[i] / two_a;
    strain(2, 3 * i) = c[i] / two_a;
    strain(2, 3 * i + 1) = b[i] / two_a;
  }
  Matrix9d k = area * strain.transpose() * membrane_elasticity(property) * strain;

  // Drilling penalty α G T ∫ (θz − ω)² dA, ω = ½(∂v/∂x − ∂u/∂y) (constant), θz linear.
  const double penalty =
      kDrillingPenalty * property.material.shear_modulus() * property.thickness;
  for (const auto& [xi, eta] : kMidsides) {
    const std::array<double, 3> l{1.0 - xi - eta, xi, eta};
    Vector9d g = Vector9d::Zero();
    for (int i = 0; i < 3; ++i) {
      g(3 * i) = 0.5 * c[i] / two_a;
      g(3 * i + 1) = -0.5 * b[i] / two_a;
      g(3 * i + 2) = l[i];
    }
    k += penalty * (area / 3.0) * g * g.transpose();
  }
  return 0.5 * (k + k.transpose());
}

ShellTriangleMatrices shell_triangle_matrices(const std::array<Eigen::Vector3d, 3>& corners,
                                              const ShellProperty& property) {
  LIMBER_DEMAND(property.thickness > 0.0 && property.material.youngs_modulus > 0.0 &&
                property.bending_ratio > 0.0 && property.nonstructural_mass >= 0.0);
  // Local frame: x along 1 → 2, z the normal by the node order.
  const Eigen::Vector3d edge_12 = corners[1] - corners[0];
  const Eigen::Vector3d normal = edge_12.cross(corners[2] - corners[0]);
  const double longest = std::max({edge_12.norm(), (corners[2] - corners[1]).norm(),
                                   (corners[0] - corners[2]).norm()});
  const double shape = normal.norm() / (longest * longest);
  if (!(shape >= kMinTriangleShapeRatio)) {
    throw InputError(fmt::format("shell triangle: expected 2 A / (longest edge)^2 >= {} (0.866 "
                                 "equilateral), got {:.3g} (a degenerate or sliver triangle)",
                                 kMinTriangleShapeRatio, shape));
  }
  Eigen::Matrix3d rotation_WL;
  rotation_WL.col(0) = edge_12.normalized();
  rotation_WL.col(2) = normal.normalized();
  rotation_WL.col(1) = rotation_WL.col(2).cross(rotation_WL.col(0));
  TriangleCoordinates xy;
  for (int k = 0; k < 3; ++k) {
    const Eigen::Vector3d local = rotation_WL.transpose() * (corners[k] - corners[0]);
    xy[k] = local.head<2>();
  }

  // Local stiffness: CST membrane with drilling + DKT plate.
  Matrix18d k_local = Matrix18d::Zero();
  scatter(cst_stiffness(xy, property), kMembraneDofs, k_local);
  scatter(dkt_stiffness(xy, property), kPlateDofs, k_local);

  // Rotate to global axes: K = Tᵀ K_L T, M = Tᵀ M_L T.
  Matrix18d t = Matrix18d::Zero();
  for (int k = 0; k < 6; ++k) t.block<3, 3>(3 * k, 3 * k) = rotation_WL.transpose();
  ShellTriangleMatrices matrices;
  matrices.stiffness = t.transpose() * k_local * t;
  matrices.mass = t.transpose() * local_mass(0.5 * twice_area(xy), property) * t;
  matrices.stiffness = 0.5 * (matrices.stiffness + matrices.stiffness.transpose()).eval();
  matrices.mass = 0.5 * (matrices.mass + matrices.mass.transpose()).eval();
  return matrices;
}

}  // namespace limber::fe
