// Element- and structure-level checks of the co-rotational beam (corotational_beam.h,
// beam_structure.h): the tangent against a central difference of the internal force on the
// Lie group (a second method), objectivity under a rigid rotation, and the undeformed tangent
// against the linear FE stiffness.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <iostream>
#include <string>

#include "core/error.h"
#include "fe/assembly.h"
#include "fe/beam_section.h"
#include "fe/fe_model_builder.h"
#include "fe/mesh_generators.h"
#include "nonlinear_beam/beam_structure.h"
#include "nonlinear_beam/corotational_beam.h"
#include "nonlinear_beam/rotation.h"

namespace limber::nonlinear_beam {
namespace {

// A steel beam with an unequal rectangular section (so that bending planes differ).
fe::BeamProperty steel_bar(bool timoshenko) {
  fe::BeamProperty property;
  property.name = "bar";
  property.material = {"steel", 210e9, 0.3, 7850.0};
  property.section = fe::rectangle_section(0.01, 0.02);
  property.timoshenko = timoshenko;
  return property;
}

// A generic 3-element beam, axis and orientation along no global axis.
fe::FeModel skew_beam(bool timoshenko) {
  fe::FeModelBuilder builder;
  builder.add_beam_property(steel_bar(timoshenko));
  fe::StraightBeamMesh mesh;
  mesh.start = Eigen::Vector3d(0.1, -0.2, 0.3);
  mesh.end = mesh.start + 0.9 * Eigen::Vector3d(1.0, 2.0, -0.5).normalized();
  mesh.orientation = Eigen::Vector3d(0.2, -0.4, 1.0);
  mesh.elements = 3;
  fe::add_straight_beam(builder, mesh);
  return std::move(builder).build();
}

// A large, generic deformed state: every node displaced by a fraction of the length and
// rotated by up to ~1 rad, differently per node (element rotations relative to the chord of
// order 0.3 rad, far from small).
BeamState deformed_state(const BeamStructure& structure) {
  BeamState state = reference_state(structure);
  for (int i = 0; i < structure.node_count(); ++i) {
    const double s = i + 1.0;
    state.positions[i] += 0.05 * Eigen::Vector3d(std::sin(s), std::cos(2.0 * s), 0.5 * s);
    state.rotations[i] =
        exp_quaternion(Eigen::Vector3d(0.3 * s, -0.2 * s + 0.1, 0.25 * std::cos(s)));
  }
  return state;
}

// Central difference of f_int along the group: x_j +- h for translations, R <- exp(+-h e) R
// for spins. Truncation O(h^2) and round-off O(eps |f| / h); with h = 1e-6 (size ~1 m, angles in
// rad) both are far below the 1e-6 relative tolerance of the tests.
Eigen::MatrixXd central_difference_tangent(const BeamStructure& structure, const BeamState& state) {
  const int n = structure.dof_count();
  const double h = 1e-6;
  Eigen::MatrixXd k(n, n);
  for (int j = 0; j < n; ++j) {
    Eigen::VectorXd delta = Eigen::VectorXd::Zero(n);
    delta(j) = h;
    BeamState plus = state;
    apply_increment(plus, delta);
    BeamState minus = state;
    apply_increment(minus, -delta);
    k.col(j) = (internal_force(structure, plus) - internal_force(structure, minus)) / (2.0 * h);
  }
  return k;
}

// Tangent = derivative of the internal force, at a large deformation, Euler-Bernoulli and
// Timoshenko. Tolerance 1e-6 relative to the largest entry: the difference quotient's own
// error is ~1e-9 relative (see central_difference_tangent); a missing geometric term (chord,
// frame rotation, eta terms, K_h) is of order |f| / L, here ~1e-3..1e-1 of the largest entry.
TEST(CorotationalBeam, TangentIsTheDerivativeOfTheInternalForce) {
  for (bool timoshenko : {false, true}) {
    const BeamStructure structure = build_beam_structure(skew_beam(timoshenko));
    const BeamState state = deformed_state(structure);
    const Eigen::MatrixXd analytic = Eigen::MatrixXd(internal_force_and_tangent(structure, state).tangent);
    const Eigen::MatrixXd numeric = central_difference_tangent(structure, state);
    const double scale = numeric.cwiseAbs().maxCoeff();
    std::cout << "timoshenko " << timoshenko << ": max |K - K_fd| / max |K_fd| = "
              << (analytic - numeric).cwiseAbs().maxCoeff() / scale << "\n";
    EXPECT_LT((analytic - numeric).cwiseAbs().maxCoeff(), 1e-6 * scale)
        << "timoshenko " << timoshenko << "\nmax |difference| "
        << (analytic - numeric).cwiseAbs().maxCoeff() << " of " << scale;
  }
}

// A rigid motion (translation and a rotation of ~2 rad) makes no strain: the internal force
// vanishes to round-off (relative to the forces of a 1 % strain), and the tangent is the
// rotated undeformed tangent.
TEST(CorotationalBeam, RigidMotionMakesNoForce) {
  const BeamStructure structure = build_beam_structure(skew_beam(false));
  const Eigen::Vector3d axis_angle(1.2, -0.7, 1.5);
  const Eigen::Matrix3d rotation = exp_so3(axis_angle);
  const Eigen::Vector3d translation(0.4, -1.0, 2.0);
  BeamState state = reference_state(structure);
  for (int i = 0; i < structure.node_count(); ++i) {
    state.positions[i] = translation + rotation * structure.reference_positions[i];
    state.rotations[i] = Eigen::Quaterniond(rotation);
  }
  const ForceAndTangent moved = internal_force_and_tangent(structure, state);
  // Force scale: EA times a 1 % strain.
  const double ea = 210e9 * 0.01 * 0.02;
  std::cout << "rigid motion: max |f_int| = " << moved.force.cwiseAbs().maxCoeff() << " N (EA = "
            << ea << " N)\n";
  EXPECT_LT(moved.force.cwiseAbs().maxCoeff(), 1e-12 * 0.01 * ea);

  // K(moved) = T K(reference) T^T with T = diag(R, R, ...).
  const Eigen::MatrixXd k0 = Eigen::MatrixXd(internal_force_and_tangent(structure, reference_state(structure)).tangent);
  Eigen::MatrixXd t = Eigen::MatrixXd::Zero(structure.dof_count(), structure.dof_count());
  for (int b = 0; b < 2 * structure.node_count(); ++b) t.block<3, 3>(3 * b, 3 * b) = rotation;
  const Eigen::MatrixXd expected = t * k0 * t.transpose();
  // Relative round-off of a sum over the element, 1e-10 of the largest stiffness entry.
  EXPECT_LT((Eigen::MatrixXd(moved.tangent) - expected).cwiseAbs().maxCoeff(),
            1e-10 * expected.cwiseAbs().maxCoeff());
}

// On the undeformed state the co-rotational tangent is limber's linear stiffness (fe::assemble):
// the element frame's rigid-body removal is exact for the linear element, whose null space is
// the rigid motions. 1e-10 of the largest entry: round-off only.
TEST(CorotationalBeam, UndeformedTangentIsTheLinearStiffness) {
  for (bool timoshenko : {false, true}) {
    const fe::FeModel model = skew_beam(timoshenko);
    const BeamStructure structure = build_beam_structure(model);
    const Eigen::MatrixXd k_nl = Eigen::MatrixXd(internal_force_and_tangent(structure, reference_state(structure)).tangent);
    const Eigen::MatrixXd k_lin = Eigen::MatrixXd(fe::assemble(model).stiffness);
    EXPECT_LT((k_nl - k_lin).cwiseAbs().maxCoeff(), 1e-10 * k_lin.cwiseAbs().maxCoeff())
        << "timoshenko " << timoshenko;
  }
}

// Models with elements this step does not treat nonlinearly are refused with an expected/got
// message naming them.
TEST(CorotationalBeam, ModelsWithShellsAreRefused) {
  fe::FeModelBuilder builder;
  builder.add_beam_property(steel_bar(false));
  fe::ShellProperty shell;
  shell.name = "plate";
  shell.material = {"steel", 210e9, 0.3, 7850.0};
  shell.thickness = 0.002;
  builder.add_shell_property(shell);
  fe::StraightBeamMesh beam;
  beam.elements = 2;
  fe::add_straight_beam(builder, beam);
  fe::RectangularPlateMesh plate;
  plate.origin = Eigen::Vector3d(0.0, 0.0, 1.0);
  plate.first_node_id = 100;
  fe::add_rectangular_plate(builder, plate);
  const fe::FeModel model = std::move(builder).build();
  try {
    build_beam_structure(model);
    ADD_FAILURE() << "no InputError";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("expected a model of beams only, got 1 shell quads"),
              std::string::npos)
        << error.what();
  }
}

// The internal force is the gradient of the strain energy along translations and spatial
// spins (a second method for f_int itself, which the tangent test takes as given): central
// difference of the energy with h = 1e-6 (truncation ~1e-12 relative, round-off eps U / h ~
// 1e-10 of the force scale), at the large deformation of the tangent test. Tolerance 1e-7 of
// the largest force entry; a wrong T_s^-T (e.g. its transpose) errs by O(theta) ~ 0.1.
TEST(CorotationalBeam, InternalForceIsTheGradientOfTheStrainEnergy) {
  for (bool timoshenko : {false, true}) {
    const BeamStructure structure = build_beam_structure(skew_beam(timoshenko));
    const BeamState state = deformed_state(structure);
    const Eigen::VectorXd force = internal_force(structure, state);
    const int n = structure.dof_count();
    const double h = 1e-6;
    Eigen::VectorXd gradient(n);
    for (int j = 0; j < n; ++j) {
      Eigen::VectorXd delta = Eigen::VectorXd::Zero(n);
      delta(j) = h;
      BeamState plus = state;
      apply_increment(plus, delta);
      BeamState minus = state;
      apply_increment(minus, -delta);
      gradient(j) = (strain_energy(structure, plus) - strain_energy(structure, minus)) / (2.0 * h);
    }
    const double scale = force.cwiseAbs().maxCoeff();
    std::cout << "timoshenko " << timoshenko << ": max |f - dU/dq| / max |f| = "
              << (force - gradient).cwiseAbs().maxCoeff() / scale << "\n";
    EXPECT_LT((force - gradient).cwiseAbs().maxCoeff(), 1e-7 * scale);
  }
}

}  // namespace
}  // namespace limber::nonlinear_beam
