#include "mode_view.h"

#include <Eigen/Eigenvalues>

#include <cmath>

namespace limber::render {
namespace {

// "x-z" when n is (nearly) a body axis, else "".
std::string plane_name(const Eigen::Vector3d& n) {
  constexpr const char* kPlanes[3] = {"y-z", "x-z", "x-y"};
  for (int c = 0; c < 3; ++c) {
    if (std::abs(n(c)) > 0.999) return std::string("body ") + kPlanes[c] + " plane";
  }
  return "";
}

}  // namespace

std::optional<ModeView> mode_view(const FlexibleMesh& mesh, Eigen::Index mode) {
  const Eigen::Index nn = mesh.nodes.rows();
  if (nn < 2 || mode >= mesh.mode_translations.cols()) return std::nullopt;
  // Principal spreads of the nodes: slender when the second is small against the first.
  const Eigen::RowVector3d mean = mesh.nodes.colwise().mean();
  const RowMatrix3d centred = mesh.nodes.rowwise() - mean;
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> spread(centred.transpose() * centred);
  const Eigen::Vector3d lambda = spread.eigenvalues();  // ascending
  if (!(lambda(2) > 0.0) || lambda(1) > kSlenderRatio * lambda(2)) return std::nullopt;
  // Dominant displacement direction of the mode.
  const Eigen::Map<const RowMatrix3d> phi(mesh.mode_translations.col(mode).data(), nn, 3);
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> motion(phi.transpose() * phi);
  if (!(motion.eigenvalues()(2) > 0.0)) return std::nullopt;
  const Eigen::Vector3d d = motion.eigenvectors().col(2);
  // The long axis without its part along d; an axial mode takes the second spread direction.
  Eigen::Vector3d a = spread.eigenvectors().col(2);
  a -= a.dot(d) * d;
  if (a.norm() < 0.1) {
    a = spread.eigenvectors().col(1);
    a -= a.dot(d) * d;
  }
  ModeView view;
  view.direction = a.normalized().cross(d).normalized();
  // The side from which the long axis, pointed along its largest component, runs left to right
  // on screen (scene.cpp: up is z, or y when looking along z; right = forward × up).
  int largest = 0;
  a.cwiseAbs().maxCoeff(&largest);
  if (a(largest) < 0.0) a = -a;
  const Eigen::Vector3d up = std::abs(view.direction.z()) > 0.99 ? Eigen::Vector3d::UnitY() : Eigen::Vector3d::UnitZ();
  if ((-view.direction).cross(up).dot(a) < 0.0) view.direction = -view.direction;
  view.plane = plane_name(view.direction);
  return view;
}

}  // namespace limber::render
