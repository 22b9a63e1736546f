// The report's deflection plot: largest elastic displacement relative to the rigid fit through
// the body's joint nodes, so a rigid part carried by the floating frame is not shown as
// deflection.
#include "run_data.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace limber::report {
namespace {

TEST(Deflection, RigidPartOfTheElasticDisplacementIsNotDeflection) {
  // A 1 m beam of 11 nodes along body x, joints at both ends; mode 1 a uniform translation
  // along y (a rigid part the floating frame left in u), mode 2 the bending w = sin(pi x) z.
  render::Results results;
  results.time = Eigen::VectorXd::Zero(1);
  render::BodyTrack beam;
  beam.name = "beam";
  beam.flexible = true;
  beam.mesh.nodes.resize(11, 3);
  beam.mesh.mode_translations = Eigen::MatrixXd::Zero(33, 2);
  for (int k = 0; k <= 10; ++k) {
    beam.mesh.nodes.row(k) << 0.1 * k, 0.0, 0.0;
    beam.mesh.mode_translations(3 * k + 1, 0) = 1.0;
    beam.mesh.mode_translations(3 * k + 2, 1) = std::sin(std::numbers::pi * 0.1 * k);
  }
  beam.position = render::RowMatrix3d::Zero(1, 3);
  beam.orientation = Eigen::RowVector4d(1, 0, 0, 0);
  beam.modal_coordinates = Eigen::RowVector2d(0.01, 0.002);
  results.bodies.push_back(beam);
  for (const auto& [name, x] : {std::pair{"A", 0.0}, std::pair{"B", 1.0}}) {
    render::JointTrack joint;
    joint.name = name;
    joint.body_i = "ground";
    joint.body_j = "beam";
    joint.position = Eigen::RowVector3d(x, 0.01, 0.0);  // where the translated end nodes are
    results.joints.push_back(joint);
  }
  std::vector<std::string> joints;
  const Eigen::VectorXd relative = max_relative_deflection(results, results.bodies[0], &joints);
  // Mid-span bending only (node 5 at x = 0.5: sin = 1): 0.002 m, to rounding; the plain |u|
  // also holds the 0.01 m translation.
  EXPECT_NEAR(relative(0), 0.002, 1e-15);
  EXPECT_NEAR(max_deflection(results.bodies[0])(0), std::hypot(0.01, 0.002), 1e-15);
  EXPECT_EQ(joints, (std::vector<std::string>{"A", "B"}));
  // B released before the sample (a hold-down, issue 28): the fit, a translation through A, leaves
  // the same bending; B is no longer named.
  results.joints[1].release_time = -1.0;
  EXPECT_NEAR(max_relative_deflection(results, results.bodies[0], &joints)(0), 0.002, 1e-15);
  EXPECT_EQ(joints, (std::vector<std::string>{"A"}));
  // Without joints: u as it is.
  results.joints.clear();
  EXPECT_NEAR(max_relative_deflection(results, results.bodies[0])(0), std::hypot(0.01, 0.002), 1e-15);
}

}  // namespace
}  // namespace limber::report
