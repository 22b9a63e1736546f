// Element-level checks of the 2-node beam (beam_element.h): static tip responses against
// closed forms, rigid-body motions, the rigid-body mass matrix against the exact one of the
// prism, invariance under rotation, and the Timoshenko matrices against a second method
// (Gauss quadrature of the interdependent interpolation shape functions).
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <Eigen/Geometry>
#include <cmath>

#include "fe/beam_element.h"
#include "fe/beam_section.h"
#include "fe_test_support.h"

namespace limber::fe {
namespace {

using testing::paper_rod_property;
using testing::relative_error;

using Matrix6d = Eigen::Matrix<double, 6, 6>;
using Vector6d = Eigen::Matrix<double, 6, 1>;

constexpr double kLength = 0.7;  // [m]; not 1, so that wrong powers of L show

// A generic element: axis and orientation not aligned with any global axis.
const Eigen::Vector3d kStart(0.3, -0.2, 0.5);
const Eigen::Vector3d kAxis = Eigen::Vector3d(1.0, 2.0, -0.5).normalized();
const Eigen::Vector3d kEnd = kStart + kLength * kAxis;
const Eigen::Vector3d kOrientation(0.2, -0.4, 1.0);

// Tip displacement/rotation of the element clamped at node 0 under a tip load (global axes).
Vector6d cantilever_tip(const BeamElementMatrices& e, const Vector6d& load) {
  const Matrix6d k_tip = e.stiffness.bottomRightCorner<6, 6>();
  return k_tip.ldlt().solve(load);
}

// Tip response in local axes for local loads: load (fx fy fz mx my mz) rotated to global,
// response rotated back.
Vector6d local_tip_response(const BeamProperty& property, const Vector6d& local_load) {
  const Eigen::Matrix3d r_lg = beam_local_axes(kStart, kEnd, kOrientation);
  const BeamElementMatrices e = beam_element_matrices(kStart, kEnd, kOrientation, property);
  Vector6d load;
  load << r_lg.transpose() * local_load.head<3>(), r_lg.transpose() * local_load.tail<3>();
  const Vector6d tip = cantilever_tip(e, load);
  Vector6d out;
  out << r_lg * tip.head<3>(), r_lg * tip.tail<3>();
  return out;
}

// One unit load component in local axes.
Vector6d unit_load(int component, double value) {
  Vector6d load = Vector6d::Zero();
  load[component] = value;
  return load;
}

TEST(BeamElement, LocalAxesFollowTheOrientationVector) {
  // x along the axis, y in the plane of x and the orientation vector (towards it), z = x × y.
  const Eigen::Matrix3d r = beam_local_axes(kStart, kEnd, kOrientation);
  EXPECT_LT((r * r.transpose() - Eigen::Matrix3d::Identity()).norm(), 1e-14);
  EXPECT_NEAR(r.determinant(), 1.0, 1e-14);
  EXPECT_LT((r.row(0).transpose() - kAxis).norm(), 1e-14);
  EXPECT_NEAR(r.row(2).dot(kOrientation), 0.0, 1e-14);
  EXPECT_GT(r.row(1).dot(kOrientation), 0.0);
}

TEST(BeamElement, CantileverTipResponsesMatchClosedForms) {
  // One element is exact for tip loads (cubic deflection, linear axial/torsion fields), so
  // only round-off remains: 1e-9 relative covers the condition number of K (~ (L/r)^2 1e2).
  const BeamProperty p = paper_rod_property();
  const double e = p.material.youngs_modulus;
  const double g = p.material.shear_modulus();
  const BeamSection& s = p.section;
  const double l = kLength;
  constexpr double kForce = 123.0;  // [N]
  constexpr double kMoment = 4.5;   // [N m]

  // Axial PL/EA and torsion TL/GJ.
  EXPECT_LT(
      relative_error(local_tip_response(p, unit_load(0, kForce))[0], kForce * l / (e * s.area)),
      1e-9);
  EXPECT_LT(relative_error(local_tip_response(p, unit_load(3, kMoment))[3],
                           kMoment * l / (g * s.torsion_constant)),
            1e-9);

  // Bending along local y (about z, Iz): v = PL^3/3EIz, rz = +PL^2/2EIz.
  const Vector6d y_load = local_tip_response(p, unit_load(1, kForce));
  EXPECT_LT(relative_error(y_load[1], kForce * l * l * l / (3.0 * e * s.inertia_z)), 1e-9);
  EXPECT_LT(relative_error(y_load[5], kForce * l * l / (2.0 * e * s.inertia_z)), 1e-9);

  // Bending along local z (about y, Iy): w = PL^3/3EIy, ry = -PL^2/2EIy.
  const Vector6d z_load = local_tip_response(p, unit_load(2, kForce));
  EXPECT_LT(relative_error(z_load[2], kForce * l * l * l / (3.0 * e * s.inertia_y)), 1e-9);
  EXPECT_LT(relative_error(z_load[4], -kForce * l * l / (2.0 * e * s.inertia_y)), 1e-9);

  // Tip moment about z: v = ML^2/2EIz, rz = ML/EIz.
  const Vector6d mz = local_tip_response(p, unit_load(5, kMoment));
  EXPECT_LT(relative_error(mz[1], kMoment * l * l / (2.0 * e * s.inertia_z)), 1e-9);
  EXPECT_LT(relative_error(mz[5], kMoment * l / (e * s.inertia_z)), 1e-9);
}

TEST(BeamElement, TimoshenkoTipDeflectionAddsShearTerm) {
  // Timoshenko cantilever: delta = PL^3/3EI + PL/(kGA), exact for one element of the
  // shear-flexible stiffness (Przemieniecki 1968), so round-off only (1e-9). A short, thick
  // section makes the shear part large (about 6 % of the tip deflection here), so the test can
  // fail.
  BeamProperty p = paper_rod_property(/*timoshenko=*/true);
  p.section = rectangle_section(0.1, 0.2);
  const double e = p.material.youngs_modulus;
  const double g = p.material.shear_modulus();
  const BeamSection& s = p.section;
  const double l = kLength;
  constexpr double kForce = 1000.0;
  const double along_y =
      kForce * l * l * l / (3.0 * e * s.inertia_z) + kForce * l / (s.shear_factor_y * g * s.area);
  const double along_z =
      kForce * l * l * l / (3.0 * e * s.inertia_y) + kForce * l / (s.shear_factor_z * g * s.area);
  EXPECT_LT(relative_error(local_tip_response(p, unit_load(1, kForce))[1], along_y), 1e-9);
  EXPECT_LT(relative_error(local_tip_response(p, unit_load(2, kForce))[2], along_z), 1e-9);
  EXPECT_GT(kForce * l / (s.shear_factor_z * g * s.area) / along_z, 0.05);
}

// Rigid-body modes of the element about point c: 3 translations, 3 small rotations.
Eigen::Matrix<double, 12, 6> rigid_modes(const Eigen::Vector3d& c) {
  Eigen::Matrix<double, 12, 6> psi = Eigen::Matrix<double, 12, 6>::Zero();
  const std::array<Eigen::Vector3d, 2> p{kStart, kEnd};
  for (int node = 0; node < 2; ++node) {
    for (int a = 0; a < 3; ++a) {
      psi(6 * node + a, a) = 1.0;
      const Eigen::Vector3d w = Eigen::Vector3d::Unit(a);
      psi.block<3, 1>(6 * node, 3 + a) = w.cross(p[node] - c);
      psi(6 * node + 3 + a, 3 + a) = 1.0;
    }
  }
  return psi;
}

TEST(BeamElement, RigidBodyMotionsProduceNoForce) {
  // K Psi = 0 up to round-off: 1e-12 relative to ||K|| ||Psi||.
  for (const bool timoshenko : {false, true}) {
    const BeamElementMatrices e =
        beam_element_matrices(kStart, kEnd, kOrientation, paper_rod_property(timoshenko));
    const Eigen::Matrix<double, 12, 6> psi = rigid_modes(Eigen::Vector3d(1.0, 0.5, -0.3));
    EXPECT_LT((e.stiffness * psi).norm(), 1e-12 * e.stiffness.norm() * psi.norm())
        << "timoshenko " << timoshenko;
  }
}

TEST(BeamElement, RigidBodyMassMatrixIsThatOfThePrism) {
  // Psi^T M Psi is exact for a consistent mass (rigid motion lies in the interpolation):
  // mass rho A L, centre at mid-length, inertia about the centre in local axes
  //   diag(rho (Iy + Iz) L, rho (A L^3/12 + Iy L), rho (A L^3/12 + Iz L)),
  // shifted to c by the parallel-axis theorem. Round-off only: 1e-12 relative.
  for (const bool timoshenko : {false, true}) {
    const BeamProperty p = paper_rod_property(timoshenko);
    const BeamElementMatrices e = beam_element_matrices(kStart, kEnd, kOrientation, p);
    const Eigen::Vector3d c(1.0, 0.5, -0.3);
    const Eigen::Matrix<double, 12, 6> psi = rigid_modes(c);
    const Matrix6d rigid = psi.transpose() * e.mass * psi;

    // Exact rigid-body mass matrix [m I, -m [d]x; m [d]x, J_c], d = centre - c.
    const double rho = p.material.density;
    const BeamSection& s = p.section;
    const double m = rho * s.area * kLength;
    const Eigen::Vector3d d = 0.5 * (kStart + kEnd) - c;
    Eigen::Matrix3d d_cross;
    d_cross << 0.0, -d.z(), d.y(), d.z(), 0.0, -d.x(), -d.y(), d.x(), 0.0;
    const Eigen::Matrix3d r_lg = beam_local_axes(kStart, kEnd, kOrientation);
    const Eigen::Vector3d j_local(
        rho * (s.inertia_y + s.inertia_z) * kLength,
        rho * (s.area * std::pow(kLength, 3) / 12.0 + s.inertia_y * kLength),
        rho * (s.area * std::pow(kLength, 3) / 12.0 + s.inertia_z * kLength));
    const Eigen::Matrix3d j_centre = r_lg.transpose() * j_local.asDiagonal() * r_lg;
    Matrix6d exact;
    exact << m * Eigen::Matrix3d::Identity(), -m * d_cross, m * d_cross,
        j_centre + m * (d.squaredNorm() * Eigen::Matrix3d::Identity() - d * d.transpose());
    EXPECT_LT((rigid - exact).norm(), 1e-12 * exact.norm()) << "timoshenko " << timoshenko;
    EXPECT_LT(relative_error(rigid(0, 0), m), 1e-13);
  }
}

TEST(BeamElement, RotatedElementHasTheSameEnergies) {
  // Rotating geometry, orientation and displacements by Q leaves d^T K d and d^T M d
  // unchanged; round-off only (1e-12 relative).
  const Eigen::Matrix3d q =
      Eigen::AngleAxisd(0.9, Eigen::Vector3d(0.3, -1.0, 0.4).normalized()).toRotationMatrix();
  const BeamProperty p = paper_rod_property(/*timoshenko=*/true);
  const BeamElementMatrices original = beam_element_matrices(kStart, kEnd, kOrientation, p);
  const BeamElementMatrices rotated =
      beam_element_matrices(q * kStart, q * kEnd, q * kOrientation, p);
  Matrix12d t = Matrix12d::Zero();
  for (int b = 0; b < 4; ++b) t.block<3, 3>(3 * b, 3 * b) = q;
  for (int trial = 0; trial < 5; ++trial) {
    const Eigen::Matrix<double, 12, 1> d = Eigen::Matrix<double, 12, 1>::Random();
    const Eigen::Matrix<double, 12, 1> d_rotated = t * d;
    const double k0 = d.dot(original.stiffness * d);
    const double m0 = d.dot(original.mass * d);
    EXPECT_LT(relative_error(d_rotated.dot(rotated.stiffness * d_rotated), k0), 1e-12);
    EXPECT_LT(relative_error(d_rotated.dot(rotated.mass * d_rotated), m0), 1e-12);
  }
}

// Interdependent interpolation of the shear-flexible beam in one plane, DOFs
// (v0, theta0, v1, theta1), theta = dv/dx - gamma, xi = x / L (Friedman & Kosmatka,
// Computers & Structures 47 (1993) 473): deflection N and rotation G shape functions.
struct PlaneShapes {
  Eigen::Vector4d n, g, dg;  // N, G and dG/dx at xi
};

PlaneShapes plane_shapes(double xi, double l, double phi) {
  const double c = 1.0 / (1.0 + phi);
  const double x2 = xi * xi;
  const double x3 = x2 * xi;
  PlaneShapes s;
  s.n << c * (1.0 - 3.0 * x2 + 2.0 * x3 + phi * (1.0 - xi)),
      c * l * (xi - 2.0 * x2 + x3 + 0.5 * phi * (xi - x2)), c * (3.0 * x2 - 2.0 * x3 + phi * xi),
      c * l * (-x2 + x3 - 0.5 * phi * (xi - x2));
  s.g << c * 6.0 * (x2 - xi) / l, c * (1.0 - 4.0 * xi + 3.0 * x2 + phi * (1.0 - xi)),
      -c * 6.0 * (x2 - xi) / l, c * (-2.0 * xi + 3.0 * x2 + phi * xi);
  s.dg << c * 6.0 * (2.0 * xi - 1.0) / (l * l), c * (-4.0 + 6.0 * xi - phi) / l,
      -c * 6.0 * (2.0 * xi - 1.0) / (l * l), c * (-2.0 + 6.0 * xi + phi) / l;
  return s;
}

TEST(BeamElement, TimoshenkoMatricesMatchShapeFunctionIntegrals) {
  // Second method: K = int EI G'G'^T + kGA (N' - G)(N' - G)^T, M = int rho A N N^T + rho I G G^T
  // by 5-point Gauss-Legendre (exact to degree 9; the integrands are of degree <= 6), where
  // N' - G = gamma is the (constant) shear strain. Round-off only: 1e-12 relative.
  BeamProperty p = paper_rod_property(/*timoshenko=*/true);
  p.section = rectangle_section(0.05, 0.09);
  const double e = p.material.youngs_modulus;
  const double g = p.material.shear_modulus();
  const double rho = p.material.density;
  const BeamSection& s = p.section;
  const double l = kLength;
  const BeamElementMatrices local = beam_local_matrices(l, p);

  constexpr double kNodes[] = {-0.9061798459386640, -0.5384693101056831, 0.0, 0.5384693101056831,
                               0.9061798459386640};
  constexpr double kWeights[] = {0.2369268850561891, 0.4786286704993665, 0.5688888888888889,
                                 0.4786286704993665, 0.2369268850561891};
  struct Plane {
    std::array<int, 4> dofs;
    std::array<double, 4> signs;
    double inertia;
    double shear_factor;
  };
  const std::array<Plane, 2> planes{
      Plane{{1, 5, 7, 11}, {1.0, 1.0, 1.0, 1.0}, s.inertia_z, s.shear_factor_y},
      Plane{{2, 4, 8, 10}, {1.0, -1.0, 1.0, -1.0}, s.inertia_y, s.shear_factor_z}};
  for (const Plane& plane : planes) {
    const double phi = 12.0 * e * plane.inertia / (plane.shear_factor * g * s.area * l * l);
    Eigen::Matrix4d k = Eigen::Matrix4d::Zero();
    Eigen::Matrix4d m = Eigen::Matrix4d::Zero();
    for (int q = 0; q < 5; ++q) {
      const double xi = 0.5 * (kNodes[q] + 1.0);
      const double w = 0.5 * kWeights[q] * l;
      const PlaneShapes sh = plane_shapes(xi, l, phi);
      // Shear strain gamma = N' - G, constant along the element (differentiating N above):
      // gamma = phi / (1 + phi) * (-1/L, -1/2, 1/L, -1/2).
      Eigen::Vector4d gamma;
      gamma << -phi / ((1.0 + phi) * l), -0.5 * phi / (1.0 + phi), phi / ((1.0 + phi) * l),
          -0.5 * phi / (1.0 + phi);
      k += w * (e * plane.inertia * sh.dg * sh.dg.transpose() +
                plane.shear_factor * g * s.area * gamma * gamma.transpose());
      m += w *
           (rho * s.area * sh.n * sh.n.transpose() + rho * plane.inertia * sh.g * sh.g.transpose());
    }
    for (int i = 0; i < 4; ++i) {
      for (int j = 0; j < 4; ++j) {
        const double sign = plane.signs[i] * plane.signs[j];
        EXPECT_NEAR(local.stiffness(plane.dofs[i], plane.dofs[j]), sign * k(i, j),
                    1e-12 * k.cwiseAbs().maxCoeff())
            << i << "," << j;
        EXPECT_NEAR(local.mass(plane.dofs[i], plane.dofs[j]), sign * m(i, j),
                    1e-12 * m.cwiseAbs().maxCoeff())
            << i << "," << j;
      }
    }
  }
}

TEST(BeamElement, DegenerateGeometryThrows) {
  const BeamProperty p = paper_rod_property();
  EXPECT_NE(testing::input_error_of([&] {
              beam_element_matrices(kStart, kStart, kOrientation, p);
            }).find("expected two distinct node positions"),
            std::string::npos);
  EXPECT_NE(testing::input_error_of([&] {
              beam_element_matrices(kStart, kEnd, 3.0 * kAxis, p);
            }).find("expected an orientation vector not parallel to the axis"),
            std::string::npos);
}

}  // namespace
}  // namespace limber::fe
