#include "mode_view.h"

#include "core/error.h"

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

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

Eigen::Vector3d mode_plane_direction(const FlexibleMesh& mesh, Eigen::Index mode) {
  if (const std::optional<ModeView> view = mode_view(mesh, mode)) return view->direction;
  LIMBER_DEMAND(mesh.nodes.rows() >= 1);
  const RowMatrix3d centred = mesh.nodes.rowwise() - mesh.nodes.colwise().mean();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> spread(centred.transpose() * centred);
  Eigen::Vector3d n = spread.eigenvectors().col(0);  // smallest spread first
  // The side towards +z, else +y, else +x (the first component that is not ~0).
  for (int c = 2; c >= 0; --c) {
    if (std::abs(n(c)) > 1e-6) {
      if (n(c) < 0.0) n = -n;
      break;
    }
  }
  return n.normalized();
}

RenderOptions mode_image_options(const BodyTrack& body, Eigen::Index mode, int width, int height) {
  RenderOptions options;
  options.width = width;
  options.height = height;
  options.ground = false;
  options.world_triad = false;
  options.time_stamp = false;
  const Eigen::Quaterniond q_WB(body.orientation(0, 0), body.orientation(0, 1), body.orientation(0, 2),
                                body.orientation(0, 3));
  const Eigen::Vector3d direction_W = q_WB.normalized() * mode_plane_direction(body.mesh, mode);
  options.camera_direction = std::array<double, 3>{direction_W.x(), direction_W.y(), direction_W.z()};
  return options;
}

}  // namespace limber::render
