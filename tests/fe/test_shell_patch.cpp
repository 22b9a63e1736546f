// Patch tests of the flat shell on the MacNeal–Harder 5-element patch (MacNeal & Harder 1985,
// "A proposed standard set of problems to test finite element accuracy", Finite Elem. Anal.
// Des. 1:3, Fig. 1): a 0.24 × 0.12 rectangle with the interior nodes (0.04, 0.02),
// (0.18, 0.03), (0.16, 0.08), (0.08, 0.08). The exact field is imposed on the 4 outer nodes,
// the 4 interior nodes are solved for; a consistent element reproduces the field exactly.
// The patch is placed in a tilted plane so the global transformation is exercised too.
#include <array>
#include <functional>
#include <limits>
#include <vector>

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include "fe/assembly.h"
#include "fe/fe_model_builder.h"
#include "fe/shell_frame.h"
#include "fe/shell_membrane.h"
#include "fe/shell_plate.h"

namespace limber::fe {
namespace {

const std::array<Eigen::Vector2d, 8> kPatchNodes{{{0.0, 0.0},
                                                  {0.24, 0.0},
                                                  {0.24, 0.12},
                                                  {0.0, 0.12},
                                                  {0.04, 0.02},
                                                  {0.18, 0.03},
                                                  {0.16, 0.08},
                                                  {0.08, 0.08}}};
const std::array<std::array<int, 4>, 5> kPatchElements{
    {{0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}, {4, 5, 6, 7}}};
constexpr int kOuterNodes = 4;

// Patch plane: rotation of the patch's (x, y, z) into global axes, and its origin.
const Eigen::Matrix3d kRotation =
    Eigen::AngleAxisd(0.9, Eigen::Vector3d(-1.0, 0.5, 2.0).normalized()).toRotationMatrix();
const Eigen::Vector3d kOrigin(1.0, 2.0, -0.5);

// MacNeal–Harder material: E = 1e6, ν = 0.25, t = 0.001.
ShellProperty patch_property() { return {"patch", {"mh", 1.0e6, 0.25, 1.0}, 0.001}; }

FeModel patch_model() {
  FeModelBuilder builder;
  for (int n = 0; n < 8; ++n) {
    builder.add_node(
        n + 1, kOrigin + kRotation * Eigen::Vector3d(kPatchNodes[n].x(), kPatchNodes[n].y(), 0.0));
  }
  const int property = builder.add_shell_property(patch_property());
  for (const auto& nodes : kPatchElements) builder.add_shell({nodes, property});
  return std::move(builder).build();
}

// Nodal DOFs of a field given in patch axes: (u, v, w, θx, θy, θz) as a function of (x, y).
using PatchField = std::function<Eigen::Matrix<double, 6, 1>(double, double)>;

// Global DOFs of the field at every node (rotated to global axes).
Eigen::VectorXd global_field(const PatchField& field) {
  Eigen::VectorXd d(6 * 8);
  for (int n = 0; n < 8; ++n) {
    const Eigen::Matrix<double, 6, 1> local = field(kPatchNodes[n].x(), kPatchNodes[n].y());
    d.segment<3>(6 * n) = kRotation * local.head<3>();
    d.segment<3>(6 * n + 3) = kRotation * local.tail<3>();
  }
  return d;
}

// Imposes `exact` on the outer nodes, solves K_ff d_f = −K_fb d_b for the interior ones.
// round_off = ε cond(K_ff), the relative forward-error bound of a backward-stable solve
// (Higham, Accuracy and Stability of Numerical Algorithms, §7.1): it is ~1e-8 here, because
// the tilted thin patch mixes membrane (E t) and bending (E t³/L²) stiffness in every global
// DOF. Nodal values are checked against it; strains and curvatures, differences of nodal
// values over elements down to 1/6 of the patch size, against 10 × round_off. A patch that
// fails the test is wrong by O(1), not by 1e-8.
struct PatchSolution {
  Eigen::VectorXd d;
  double round_off = 0.0;
};
PatchSolution solve_patch(const FeModel& model, const Eigen::VectorXd& exact) {
  const Eigen::MatrixXd k = Eigen::MatrixXd(assemble(model).stiffness);
  const int nb = 6 * kOuterNodes;
  const int nf = 6 * 8 - nb;
  const Eigen::MatrixXd k_ff = k.bottomRightCorner(nf, nf);
  PatchSolution solution{exact, 0.0};
  solution.d.tail(nf) = k_ff.ldlt().solve(-k.bottomLeftCorner(nf, nb) * exact.head(nb));
  const Eigen::VectorXd lambda = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(k_ff).eigenvalues();
  solution.round_off =
      std::numeric_limits<double>::epsilon() * lambda.maxCoeff() / lambda.minCoeff();
  return solution;
}

// Element corners and the element's nodal DOFs rotated into its local frame.
struct LocalElement {
  ShellFrame frame;
  Eigen::Matrix<double, 24, 1> dofs;
};
LocalElement local_element(const FeModel& model, const Eigen::VectorXd& d, int element) {
  std::array<Eigen::Vector3d, 4> corners;
  for (int k = 0; k < 4; ++k) corners[k] = model.node_positions[kPatchElements[element][k]];
  LocalElement e{shell_frame(corners), {}};
  const Eigen::Matrix3d rotation_LW = e.frame.rotation_WL.transpose();
  for (int k = 0; k < 4; ++k) {
    const int node = kPatchElements[element][k];
    e.dofs.segment<3>(6 * k) = rotation_LW * d.segment<3>(6 * node);
    e.dofs.segment<3>(6 * k + 3) = rotation_LW * d.segment<3>(6 * node + 3);
  }
  return e;
}

// Points where strains are sampled: the 4 corners, the centre and an off-centre point.
const std::array<Eigen::Vector2d, 6> kSamplePoints{
    {{-1.0, -1.0}, {1.0, -1.0}, {1.0, 1.0}, {-1.0, 1.0}, {0.0, 0.0}, {0.3, -0.7}}};

// Strain tensor (εxx, εyy, εxy) ↔ Voigt vector (εxx, εyy, 2εxy).
Eigen::Matrix2d tensor(const Eigen::Vector3d& voigt) {
  Eigen::Matrix2d t;
  t << voigt(0), 0.5 * voigt(2), 0.5 * voigt(2), voigt(1);
  return t;
}

TEST(ShellPatch, MembraneReproducesConstantStrain) {
  // MacNeal–Harder membrane field: u = 1e-3 (x + y/2), v = 1e-3 (y + x/2), so
  // εxx = εyy = γxy = 1e-3 and the in-plane rotation ω = ½(v,x − u,y) = 0 (θz = 0).
  const PatchField field = [](double x, double y) {
    Eigen::Matrix<double, 6, 1> f = Eigen::Matrix<double, 6, 1>::Zero();
    f(0) = 1e-3 * (x + 0.5 * y);
    f(1) = 1e-3 * (y + 0.5 * x);
    return f;
  };
  const FeModel model = patch_model();
  const Eigen::VectorXd exact = global_field(field);
  const auto [d, round_off] = solve_patch(model, exact);

  // Interior DOFs exact to round-off (see solve_patch).
  EXPECT_LT((d - exact).cwiseAbs().maxCoeff(), round_off * exact.cwiseAbs().maxCoeff());

  // Constant strain everywhere in every element (incompatible modes recovered), equal to the
  // exact strain rotated into the element axes.
  const Eigen::Matrix2d exact_patch = tensor(Eigen::Vector3d(1e-3, 1e-3, 1e-3));
  for (int element = 0; element < 5; ++element) {
    const LocalElement e = local_element(model, d, element);
    // Element axes (e1, e2) in patch axes.
    const Eigen::Matrix<double, 3, 2> axes =
        kRotation.transpose() * e.frame.rotation_WL.leftCols<2>();
    const Eigen::Matrix2d exact_local =
        axes.topRows<2>().transpose() * exact_patch * axes.topRows<2>();
    Vector12d membrane;
    for (int k = 0; k < 4; ++k) {
      membrane.segment<2>(3 * k) = e.dofs.segment<2>(6 * k);
      membrane(3 * k + 2) = e.dofs(6 * k + 5);
    }
    for (const Eigen::Vector2d& p : kSamplePoints) {
      const Eigen::Matrix2d strain =
          tensor(membrane_strain(e.frame.xy, patch_property(), membrane, p.x(), p.y()));
      EXPECT_LT((strain - exact_local).cwiseAbs().maxCoeff(), 10.0 * round_off * 1e-3)
          << "element " << element << " at (" << p.x() << ", " << p.y() << ")";
    }
  }
}

TEST(ShellPatch, BendingReproducesConstantCurvature) {
  // Constant-curvature field w = ½ (a x² + b y² + c x y) with the Kirchhoff rotations
  // θx = ∂w/∂y, θy = −∂w/∂x (zero transverse shear): κ = (−a, −b, −c), constant moments
  // M = D κ, zero shear force. MITC4's tying-point strains vanish for it exactly
  // (Dvorkin & Bathe 1984), so the patch must reproduce it to round-off.
  const double a = 2e-3, b = -1e-3, c = 3e-3;
  const PatchField field = [=](double x, double y) {
    Eigen::Matrix<double, 6, 1> f = Eigen::Matrix<double, 6, 1>::Zero();
    f(2) = 0.5 * (a * x * x + b * y * y + c * x * y);
    f(3) = b * y + 0.5 * c * x;
    f(4) = -(a * x + 0.5 * c * y);
    return f;
  };
  const FeModel model = patch_model();
  const Eigen::VectorXd exact = global_field(field);
  const auto [d, round_off] = solve_patch(model, exact);

  // Interior DOFs exact to round-off (see solve_patch).
  EXPECT_LT((d - exact).cwiseAbs().maxCoeff(), round_off * exact.cwiseAbs().maxCoeff());

  // Curvature tensor in patch axes: ∂θ-components give κ = −Hessian(w).
  Eigen::Matrix2d exact_patch;
  exact_patch << -a, -0.5 * c, -0.5 * c, -b;
  const double scale = exact_patch.cwiseAbs().maxCoeff();
  for (int element = 0; element < 5; ++element) {
    const LocalElement e = local_element(model, d, element);
    const Eigen::Matrix<double, 3, 2> axes =
        kRotation.transpose() * e.frame.rotation_WL.leftCols<2>();
    const Eigen::Matrix2d exact_local =
        axes.topRows<2>().transpose() * exact_patch * axes.topRows<2>();
    Vector12d plate;
    for (int k = 0; k < 4; ++k) plate.segment<3>(3 * k) = e.dofs.segment<3>(6 * k + 2);
    for (const Eigen::Vector2d& p : kSamplePoints) {
      const Eigen::Matrix2d curvature = tensor(plate_curvature(e.frame.xy, plate, p.x(), p.y()));
      EXPECT_LT((curvature - exact_local).cwiseAbs().maxCoeff(), 10.0 * round_off * scale)
          << "element " << element << " at (" << p.x() << ", " << p.y() << ")";
      // Assumed shear strain vanishes: compare with the rotations' size (scale × patch
      // length 0.24 m).
      EXPECT_LT(plate_shear_strain(e.frame.xy, plate, p.x(), p.y()).norm(),
                10.0 * round_off * scale * 0.24);
    }
  }
}

}  // namespace
}  // namespace limber::fe
