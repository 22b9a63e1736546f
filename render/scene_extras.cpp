#include "scene_extras.h"

#include "world_triad.h"

#include <vtkActor.h>
#include <vtkAlgorithmOutput.h>
#include <vtkAppendPolyData.h>
#include <vtkArrowSource.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkConeSource.h>
#include <vtkCylinderSource.h>
#include <vtkLineSource.h>
#include <vtkMatrix4x4.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>

#include <fmt/core.h>

#include <algorithm>
#include <cmath>

namespace limber::render {
namespace {

// Glyph sizes as fractions of the scene radius.
constexpr double kPinLength = 0.12, kPinRadius = 0.014;
constexpr double kSlideArrowLength = 0.22;  // scaled uniformly: tip radius 0.1 of the length
// Force and torque arrows: lateral scale of VTK's unit arrow (tip radius 0.1, shaft 0.03 of it).
constexpr double kForceArrowWidth = 0.15;
// The largest force's (torque's) arrow is about this fraction of the scene radius.
constexpr double kForcePeakLength = 0.25;
// Torque arrows: two heads, each this fraction of the arrow's length, the second behind the first.
constexpr double kTorqueHeadLength = 0.25;
// Torques below this fraction of (largest force x scene radius) are round-off of the reaction
// solve (a planar mechanism's out-of-plane moments come out near 1e-10 N m for 30 N forces):
// no arrows, the legend says so.
constexpr double kTorqueNoise = 1e-6;

Eigen::Quaterniond quaternion_row(const RowMatrix4d& q, Eigen::Index i) {
  return Eigen::Quaterniond(q(i, 0), q(i, 1), q(i, 2), q(i, 3)).normalized();
}

// A 4x4 matrix with columns (axis_x, axis_y, axis_z, origin).
void set_columns(vtkMatrix4x4* m, const Eigen::Matrix3d& axes, const Eigen::Vector3d& origin) {
  m->Identity();
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) m->SetElement(r, c, axes(r, c));
    m->SetElement(r, 3, origin(r));
  }
}

// Two unit vectors completing `e` (unit) to a right-handed basis.
Eigen::Matrix3d basis_along(const Eigen::Vector3d& e) {
  const Eigen::Vector3d helper = std::abs(e.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
  const Eigen::Vector3d n1 = e.cross(helper).normalized();
  Eigen::Matrix3d axes;
  axes << e, n1, e.cross(n1);
  return axes;
}

vtkSmartPointer<vtkActor> flat_actor(vtkRenderer* renderer, vtkAlgorithmOutput* port,
                                     const std::array<double, 3>& color) {
  auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
  mapper->SetInputConnection(port);
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(color[0], color[1], color[2]);
  // Mostly ambient: the glyph keeps its colour whichever way it faces the lights.
  actor->GetProperty()->SetAmbient(0.6);
  actor->GetProperty()->SetDiffuse(0.4);
  actor->SetUserMatrix(vtkSmartPointer<vtkMatrix4x4>::New());
  renderer->AddActor(actor);
  return actor;
}

// How far the shapes of the joint's bodies that hold the joint point reach from it along the
// axis (either way), at the first sample [m]; 0 when no shape holds the point. Boxes by their
// edges, cylinders (local z) by their bounding box, spheres by their radius.
double reach_along(const Results& results, const JointTrack& joint, const Eigen::Vector3d& axis_W) {
  double reach = 0.0;
  const Eigen::Vector3d p_W = joint.position.row(0).transpose();
  for (const BodyTrack& body : results.bodies) {
    if (body.name != joint.body_i && body.name != joint.body_j) continue;
    const BodyState state = body_state(body, SampleBracket{});
    for (const Shape& shape : body.shapes) {
      const Eigen::Vector3d half = shape.type == Shape::Type::kBox ? Eigen::Vector3d(0.5 * shape.size)
                                   : shape.type == Shape::Type::kCylinder
                                       ? Eigen::Vector3d(shape.size.x(), shape.size.x(), 0.5 * shape.size.z())
                                       : Eigen::Vector3d::Constant(shape.size.x());
      const Eigen::Matrix3d R_WS = (state.orientation * shape.offset_orientation).toRotationMatrix();
      const Eigen::Vector3d local = R_WS.transpose() * (p_W - state.position - state.orientation * shape.offset_position);
      if (((local.cwiseAbs() - half).array() > 1e-9).any()) continue;  // the shape does not hold the point
      // Support of the box along the axis from its centre, plus the point's offset along it.
      const Eigen::Vector3d a = R_WS.transpose() * axis_W;
      reach = std::max(reach, a.cwiseAbs().dot(half) + std::abs(a.dot(local)));
    }
  }
  return reach;
}

// VTK's unit arrow along x (0..1) with a second head behind its tip: the moment symbol.
vtkSmartPointer<vtkAppendPolyData> double_headed_arrow() {
  auto arrow = vtkSmartPointer<vtkArrowSource>::New();
  arrow->SetTipLength(kTorqueHeadLength);
  arrow->SetTipResolution(16);
  arrow->SetShaftResolution(16);
  auto second = vtkSmartPointer<vtkConeSource>::New();
  second->SetHeight(kTorqueHeadLength);
  second->SetRadius(0.1);  // vtkArrowSource's tip radius
  second->SetResolution(16);
  second->SetDirection(1.0, 0.0, 0.0);
  second->SetCenter(1.0 - 1.5 * kTorqueHeadLength, 0.0, 0.0);
  auto both = vtkSmartPointer<vtkAppendPolyData>::New();
  both->AddInputConnection(arrow->GetOutputPort());
  both->AddInputConnection(second->GetOutputPort());
  return both;
}

// The largest row norm of a joint's [ns, 3] reaction over the samples in [t0, t1] (0 rows: 0).
double peak_norm(const Results& results, const RowMatrix3d& values, double t0, double t1) {
  double peak = 0.0;
  if (values.rows() != results.sample_count()) return peak;
  for (Eigen::Index k = 0; k < values.rows(); ++k) {
    if (results.time(k) >= t0 && results.time(k) <= t1) peak = std::max(peak, values.row(k).norm());
  }
  return peak;
}

// A row of a [ns, 3] track between samples, linearly.
Eigen::Vector3d interpolate(const RowMatrix3d& values, const SampleBracket& at) {
  const Eigen::Index next = std::min<Eigen::Index>(at.i + 1, values.rows() - 1);
  return (1.0 - at.w) * values.row(at.i).transpose() + at.w * values.row(next).transpose();
}

bool is_pin(const std::string& type) { return type == "revolute" || type == "cylindrical"; }
bool is_slide(const std::string& type) { return type == "translational"; }

}  // namespace

void marker_pose(const MarkerTrack& marker, const SampleBracket& at, Eigen::Vector3d& p_W,
                 Eigen::Matrix3d& R_WM) {
  const Eigen::Index j = std::min<Eigen::Index>(at.i + 1, marker.position.rows() - 1);
  p_W = (1.0 - at.w) * marker.position.row(at.i).transpose() + at.w * marker.position.row(j).transpose();
  R_WM = quaternion_row(marker.orientation, at.i).slerp(at.w, quaternion_row(marker.orientation, j)).toRotationMatrix();
}

ArrowScale arrow_scale(double peak, double scene_radius) {
  // A round arrow length stands for a round value: L_ref m = V_ref, V_ref = round(peak / 2).
  return {round_length(0.5 * peak), round_length(0.5 * kForcePeakLength * scene_radius)};
}

std::array<double, 2> slide_travel(const JointTrack& joint) {
  std::array<double, 2> travel{0.0, 0.0};
  for (Eigen::Index k = 0; k < joint.marker_i.position.rows(); ++k) {
    const Eigen::Vector3d z_i = joint.marker_i.rotation(k).col(2);
    const double s = z_i.dot(joint.marker_j.position.row(k) - joint.marker_i.position.row(k));
    travel[0] = k == 0 ? s : std::min(travel[0], s);
    travel[1] = k == 0 ? s : std::max(travel[1], s);
  }
  return travel;
}

struct SceneExtras::Impl {
  const Results& results;
  RenderOptions options;
  vtkRenderer* renderer = nullptr;
  double radius = 1.0;
  // Per joint (results.joints order): its axis glyph and rail, or null; the glyph's length.
  std::vector<vtkSmartPointer<vtkActor>> glyphs, rails;
  std::vector<double> glyph_length;
  std::vector<std::array<double, 2>> travel;
  // The arrows' renderer (layer 1) and, per joint, its force and torque arrows, or null.
  vtkSmartPointer<vtkRenderer> overlay;
  std::vector<vtkSmartPointer<vtkActor>> arrows, torque_arrows;
  double newtons_per_metre = 0.0, newton_metres_per_metre = 0.0;
  // Ghost outlines: per flexible body, its fits, points and the body index.
  struct Ghost {
    std::size_t body = 0;
    TimedRigidFit fit;
    vtkSmartPointer<vtkPoints> points;
    vtkSmartPointer<vtkPolyData> outline;
  };
  std::vector<Ghost> ghosts;
  std::vector<vtkSmartPointer<vtkTextActor>> texts;

  Impl(const Results& r, const RenderOptions& o) : results(r), options(o) {}

  void add_joint_glyph(const JointTrack& joint) {
    vtkSmartPointer<vtkActor> glyph, rail;
    double length = 0.0;
    if (joint.has_markers() && is_pin(joint.type)) {
      // Centred on the joint, 1.5 times the reach of the shapes around it each way.
      length = std::max(kPinLength * radius, 3.0 * reach_along(results, joint, joint.marker_j.rotation(0).col(2)));
      // VTK's cylinder lies along its y: the matrix maps y to the pin axis.
      auto cylinder = vtkSmartPointer<vtkCylinderSource>::New();
      cylinder->SetRadius(std::max(kPinRadius * radius, 0.1 * length));
      cylinder->SetHeight(length);
      cylinder->SetResolution(24);
      glyph = flat_actor(renderer, cylinder->GetOutputPort(), kPinAxisColor);
    } else if (joint.has_markers() && is_slide(joint.type)) {
      // From the joint point: 1.5 times the shapes' reach.
      length = std::max(kSlideArrowLength * radius, 1.5 * reach_along(results, joint, joint.marker_i.rotation(0).col(2)));
      auto arrow = vtkSmartPointer<vtkArrowSource>::New();
      arrow->SetTipResolution(16);
      arrow->SetShaftResolution(16);
      glyph = flat_actor(renderer, arrow->GetOutputPort(), kSlideAxisColor);
      auto line = vtkSmartPointer<vtkLineSource>::New();
      line->SetPoint1(0.0, 0.0, 0.0);
      line->SetPoint2(1.0, 0.0, 0.0);
      rail = flat_actor(renderer, line->GetOutputPort(), kRailColor);
      rail->GetProperty()->SetLineWidth(std::max(2.0f, static_cast<float>(options.height) / 240.0f));
      rail->GetProperty()->SetAmbient(1.0);
      rail->GetProperty()->SetDiffuse(0.0);
    }
    glyphs.push_back(glyph);
    glyph_length.push_back(length);
    rails.push_back(rail);
    travel.push_back(rail ? slide_travel(joint) : std::array<double, 2>{0.0, 0.0});
  }

  void add_ghost(std::size_t b) {
    const BodyTrack& body = results.bodies[b];
    Ghost ghost;
    ghost.body = b;
    ghost.fit = timed_rigid_fit(results, body);
    ghost.points = vtkSmartPointer<vtkPoints>::New();
    ghost.points->SetDataTypeToDouble();
    ghost.points->SetNumberOfPoints(body.mesh.nodes.rows());
    // Beams as lines, quads as their closed outlines.
    auto lines = vtkSmartPointer<vtkCellArray>::New();
    for (Eigen::Index e = 0; e < body.mesh.lines.rows(); ++e) {
      const vtkIdType ids[2] = {body.mesh.lines(e, 0), body.mesh.lines(e, 1)};
      lines->InsertNextCell(2, ids);
    }
    for (Eigen::Index e = 0; e < body.mesh.quads.rows(); ++e) {
      const vtkIdType ids[5] = {body.mesh.quads(e, 0), body.mesh.quads(e, 1), body.mesh.quads(e, 2),
                                body.mesh.quads(e, 3), body.mesh.quads(e, 0)};
      lines->InsertNextCell(5, ids);
    }
    ghost.outline = vtkSmartPointer<vtkPolyData>::New();
    ghost.outline->SetPoints(ghost.points);
    ghost.outline->SetLines(lines);
    auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
    mapper->SetInputData(ghost.outline);
    mapper->ScalarVisibilityOff();
    auto actor = vtkSmartPointer<vtkActor>::New();
    actor->SetMapper(mapper);
    actor->GetProperty()->SetColor(kGhostColor[0], kGhostColor[1], kGhostColor[2]);
    actor->GetProperty()->SetLineWidth(std::max(1.5f, static_cast<float>(options.height) / 360.0f));
    actor->GetProperty()->SetAmbient(1.0);
    actor->GetProperty()->SetDiffuse(0.0);
    actor->GetProperty()->SetOpacity(0.8);
    renderer->AddActor(actor);
    ghosts.push_back(ghost);
  }

  // A legend line of an arrow scale at height y (normalised viewport).
  void add_legend(const std::string& text, const std::array<double, 3>& color, double y) {
    auto legend = vtkSmartPointer<vtkTextActor>::New();
    legend->SetInput(text.c_str());
    legend->GetTextProperty()->SetFontSize(std::max(10, options.height / 45));  // >= 14 px tall at 720p
    legend->GetTextProperty()->SetColor(color[0] * 0.8, color[1] * 0.8, color[2] * 0.8);
    legend->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
    legend->GetPositionCoordinate()->SetValue(0.02, y);
    renderer->AddViewProp(legend);
    texts.push_back(legend);
  }

  void add_reaction_arrows(double t0, double t1) {
    overlay = overlay_layer(renderer);
    // The largest reaction force and torque over the samples in [t0, t1].
    double peak_force = 0.0, peak_torque = 0.0;
    for (const JointTrack& joint : results.joints) {
      peak_force = std::max(peak_force, peak_norm(results, joint.force_ground, t0, t1));
      peak_torque = std::max(peak_torque, peak_norm(results, joint.torque_ground, t0, t1));
    }
    const bool torque_noise = peak_torque > 0.0 && peak_torque <= kTorqueNoise * peak_force * radius;
    for (const JointTrack& joint : results.joints) {
      vtkSmartPointer<vtkActor> force, torque;
      if (joint.force_ground.rows() == results.sample_count() && peak_force > 0.0) {
        auto source = vtkSmartPointer<vtkArrowSource>::New();
        source->SetTipResolution(16);
        source->SetShaftResolution(16);
        force = flat_actor(overlay, source->GetOutputPort(), kForceColor);
      }
      if (joint.torque_ground.rows() == results.sample_count() && peak_torque > 0.0 && !torque_noise) {
        torque = flat_actor(overlay, double_headed_arrow()->GetOutputPort(), kTorqueColor);
      }
      arrows.push_back(force);
      torque_arrows.push_back(torque);
    }
    // Scales and their legends, bottom left above the time stamp.
    if (peak_force > 0.0) {
      const ArrowScale scale = arrow_scale(peak_force, radius);
      newtons_per_metre = scale.per_metre();
      add_legend(fmt::format("force arrows: {:g} m = {:g} N (reaction on body j; peak {:.3g} N)",
                             scale.length, scale.value, peak_force),
                 kForceColor, 0.08);
    }
    if (torque_noise) {
      add_legend(fmt::format("torques ~ 0 (peak {:.3g} N m, below {:g} of the largest force x the scene "
                             "radius): not drawn",
                             peak_torque, kTorqueNoise),
                 kTorqueColor, 0.125);
    } else if (peak_torque > 0.0) {
      const ArrowScale scale = arrow_scale(peak_torque, radius);
      newton_metres_per_metre = scale.per_metre();
      add_legend(fmt::format("torque arrows (double head, right-hand rule): {:g} m = {:g} N m "
                             "(reaction on body j about the joint; peak {:.3g} N m)",
                             scale.length, scale.value, peak_torque),
                 kTorqueColor, peak_force > 0.0 ? 0.125 : 0.08);
    }
  }

  // Places a unit arrow along `vector` from `origin`, |vector| / per_metre long; hidden when
  // shorter than a speck.
  void place_arrow(vtkActor* arrow, const Eigen::Vector3d& origin, const Eigen::Vector3d& vector,
                   double per_metre) {
    const double length = vector.norm() / per_metre;
    arrow->SetVisibility(length > 1e-9 * radius);
    if (length <= 1e-9 * radius) return;
    Eigen::Matrix3d axes = basis_along(vector.normalized());
    axes.col(0) *= length;
    axes.col(1) *= kForceArrowWidth * radius;
    axes.col(2) *= kForceArrowWidth * radius;
    set_columns(arrow->GetUserMatrix(), axes, origin);
    arrow->Modified();
  }
};

SceneExtras::SceneExtras(const Results& results, const RenderOptions& options, vtkRenderer* renderer,
                         double scene_radius, double t0, double t1)
    : impl_(std::make_unique<Impl>(results, options)) {
  Impl& s = *impl_;
  s.renderer = renderer;
  s.radius = std::max(scene_radius, 1e-6);
  if (options.joint_axes) {
    for (const JointTrack& joint : results.joints) s.add_joint_glyph(joint);
  }
  if (options.ghost) {
    for (std::size_t b = 0; b < results.bodies.size(); ++b) {
      if (results.bodies[b].flexible) s.add_ghost(b);
    }
  }
  if (options.forces) s.add_reaction_arrows(t0, t1);
}

SceneExtras::~SceneExtras() = default;

std::vector<Eigen::Vector3d> SceneExtras::glyph_corners() const {
  std::vector<Eigen::Vector3d> corners;
  for (const auto* actors : {&impl_->glyphs, &impl_->rails}) {
    for (const vtkSmartPointer<vtkActor>& actor : *actors) {
      if (!actor) continue;
      const double* b = actor->GetBounds();  // x min, x max, y min, ..., user matrix applied
      for (int c = 0; c < 8; ++c) corners.emplace_back(b[c & 1], b[2 + ((c >> 1) & 1)], b[4 + ((c >> 2) & 1)]);
    }
  }
  return corners;
}

void SceneExtras::update(const SampleBracket& at) {
  Impl& s = *impl_;
  for (std::size_t j = 0; j < s.glyphs.size(); ++j) {
    if (!s.glyphs[j]) continue;
    const JointTrack& joint = s.results.joints[j];
    // A released hold-down is gone (with its rail).
    s.glyphs[j]->SetVisibility(joint.held_at(at.t) ? 1 : 0);
    if (s.rails[j]) s.rails[j]->SetVisibility(joint.held_at(at.t) ? 1 : 0);
    Eigen::Vector3d p_i, p_j;
    Eigen::Matrix3d R_i, R_j;
    marker_pose(joint.marker_i, at, p_i, R_i);
    marker_pose(joint.marker_j, at, p_j, R_j);
    if (is_pin(joint.type)) {
      // Cylinder: its y along the pin axis z_j, centred on the joint point.
      Eigen::Matrix3d axes;
      axes << R_j.col(0), R_j.col(2), -R_j.col(1);
      set_columns(s.glyphs[j]->GetUserMatrix(), axes, p_j);
    } else {
      // Arrow (VTK's along x, length 1) along z_i from the joint point; rail over the travel.
      Eigen::Matrix3d axes = basis_along(R_i.col(2)) * s.glyph_length[j];
      set_columns(s.glyphs[j]->GetUserMatrix(), axes, p_j);
      const double span = s.travel[j][1] - s.travel[j][0];
      const double margin = std::max(0.25 * span, 0.15 * s.radius);
      Eigen::Matrix3d rail = basis_along(R_i.col(2));
      rail.col(0) *= span + 2.0 * margin;
      set_columns(s.rails[j]->GetUserMatrix(), rail, p_i + (s.travel[j][0] - margin) * R_i.col(2));
      s.rails[j]->Modified();
    }
    s.glyphs[j]->Modified();
  }
  // Ghosts: nodes at the rigid fit's pose, without the relative deflection.
  for (Impl::Ghost& ghost : s.ghosts) {
    const BodyTrack& body = s.results.bodies[ghost.body];
    const BodyState state = body_state(body, at);
    const RowMatrix3d u = elastic_displacements(body.mesh, state);
    const RowMatrix3d u_rel = relative_displacements(ghost.fit.at(at.t).basis, body.mesh.nodes, u);
    const Eigen::Matrix3d R = state.orientation.toRotationMatrix();
    const RowMatrix3d x_W =
        ((body.mesh.nodes + (u - u_rel)) * R.transpose()).rowwise() + state.position.transpose();
    for (Eigen::Index k = 0; k < x_W.rows(); ++k) ghost.points->SetPoint(k, x_W(k, 0), x_W(k, 1), x_W(k, 2));
    ghost.points->Modified();
    ghost.outline->Modified();
  }
  // Force and torque arrows from the joint point along F and T.
  for (std::size_t j = 0; j < s.arrows.size(); ++j) {
    const JointTrack& joint = s.results.joints[j];
    const Eigen::Vector3d p_W = joint_position(joint, at);
    if (s.arrows[j]) s.place_arrow(s.arrows[j], p_W, interpolate(joint.force_ground, at), s.newtons_per_metre);
    if (s.torque_arrows[j]) {
      s.place_arrow(s.torque_arrows[j], p_W, interpolate(joint.torque_ground, at), s.newton_metres_per_metre);
    }
  }
}

std::vector<vtkSmartPointer<vtkTextActor>> SceneExtras::texts() const { return impl_->texts; }

double SceneExtras::newtons_per_metre() const { return impl_->newtons_per_metre; }

double SceneExtras::newton_metres_per_metre() const { return impl_->newton_metres_per_metre; }

vtkRenderer* SceneExtras::overlay() const { return impl_->overlay; }

vtkSmartPointer<vtkRenderer> overlay_layer(vtkRenderer* scene) {
  // Layer 1, the scene's camera, its own depth buffer, the colour kept.
  auto overlay = vtkSmartPointer<vtkRenderer>::New();
  overlay->SetLayer(1);
  overlay->SetActiveCamera(scene->GetActiveCamera());
  overlay->InteractiveOff();
  return overlay;
}

}  // namespace limber::render
