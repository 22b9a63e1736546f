#include "scene.h"

#include "body_pose.h"
#include "camera_fit.h"
#include "color_map.h"
#include "flexible_view.h"
#include "length_unit.h"
#include "flat_shading.h"
#include "stress_reader.h"
#include "core/error.h"
#include "relative_deflection.h"
#include "scene_extras.h"
#include "scene_labels.h"
#include "scene_layout.h"
#include "world_triad.h"

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkCubeSource.h>
#include <vtkCylinderSource.h>
#include <vtkLightKit.h>
#include <vtkLookupTable.h>
#include <vtkMatrix4x4.h>
#include <vtkPlaneSource.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkSphereSource.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

namespace limber::render {
namespace {

// The camera's up: ground z, or y when looking along z.
Eigen::Vector3d up_hint(const Eigen::Vector3d& direction) {
  return std::abs(direction.z()) > 0.99 ? Eigen::Vector3d::UnitY() : Eigen::Vector3d::UnitZ();
}

// 4x4 homogeneous matrix of a pose (position, rotation).
void set_pose(vtkMatrix4x4* matrix, const Eigen::Vector3d& p, const Eigen::Matrix3d& R) {
  matrix->Identity();
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) matrix->SetElement(r, c, R(r, c));
    matrix->SetElement(r, 3, p(r));
  }
}

// A source for a primitive, centred at its own origin; cylinders along local z.
vtkSmartPointer<vtkPolyDataMapper> primitive_mapper(const Shape& shape) {
  auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
  switch (shape.type) {
    case Shape::Type::kBox: {
      auto source = vtkSmartPointer<vtkCubeSource>::New();
      source->SetXLength(shape.size.x());
      source->SetYLength(shape.size.y());
      source->SetZLength(shape.size.z());
      mapper->SetInputConnection(source->GetOutputPort());
      break;
    }
    case Shape::Type::kCylinder: {
      auto source = vtkSmartPointer<vtkCylinderSource>::New();
      source->SetRadius(shape.size.x());
      source->SetHeight(shape.size.z());
      source->SetResolution(32);
      mapper->SetInputConnection(source->GetOutputPort());
      break;
    }
    case Shape::Type::kSphere: {
      auto source = vtkSmartPointer<vtkSphereSource>::New();
      source->SetRadius(shape.size.x());
      source->SetThetaResolution(32);
      source->SetPhiResolution(16);
      mapper->SetInputConnection(source->GetOutputPort());
      break;
    }
  }
  return mapper;
}

// Rotation of the primitive's own axes into the shape frame (VTK cylinders lie along y).
Eigen::Matrix3d primitive_axes(const Shape& shape) {
  if (shape.type != Shape::Type::kCylinder) return Eigen::Matrix3d::Identity();
  return Eigen::AngleAxisd(M_PI / 2.0, Eigen::Vector3d::UnitX()).toRotationMatrix();
}

// Radius of a sphere around the shape's origin that holds it [m].
double shape_radius(const Shape& shape) {
  switch (shape.type) {
    case Shape::Type::kBox: return 0.5 * shape.size.norm();
    case Shape::Type::kCylinder: return std::hypot(shape.size.x(), 0.5 * shape.size.z());
    case Shape::Type::kSphere: return shape.size.x();
  }
  return 0.0;
}

// A primitive's box in its own axes (a cylinder's about its axis z, a sphere's cube) [m].
CameraBox shape_box(const Shape& shape) {
  const Eigen::Vector3d half = shape.type == Shape::Type::kBox        ? Eigen::Vector3d(0.5 * shape.size)
                               : shape.type == Shape::Type::kCylinder ? Eigen::Vector3d(shape.size.x(), shape.size.x(),
                                                                                        0.5 * shape.size.z())
                                                                      : Eigen::Vector3d::Constant(shape.size.x());
  CameraBox box;
  box.lo = -half;
  box.hi = half;
  return box;
}

// A box of no size at the origin: a point's eight corners.
CameraBox point_box() {
  CameraBox box;
  box.add(Eigen::Vector3d::Zero());
  return box;
}

// The samples in [t0, t1]; the sample bracket at t0 when none lies inside.
std::vector<SampleBracket> samples_in(const Eigen::VectorXd& time, double t0, double t1) {
  std::vector<SampleBracket> samples;
  for (Eigen::Index i = 0; i < time.size(); ++i) {
    if (time(i) >= t0 && time(i) <= t1) samples.push_back({i, 0.0, time(i)});
  }
  if (samples.empty()) samples.push_back(bracket(time, t0));
  return samples;
}

// Axis-aligned bounds accumulated from points and spheres, ground axes.
struct Bounds : CameraBox {
  Eigen::Vector3d center() const { return 0.5 * (lo + hi); }
  double radius() const { return 0.5 * (hi - lo).norm(); }
};

}  // namespace

struct RigidShapeView {
  const BodyTrack* body = nullptr;
  const Shape* shape = nullptr;
  vtkSmartPointer<vtkActor> actor;
};

struct Scene::Impl {
  const Results& results;
  RenderOptions options;
  vtkSmartPointer<vtkRenderer> renderer = vtkSmartPointer<vtkRenderer>::New();
  vtkSmartPointer<vtkLookupTable> lut = vtkSmartPointer<vtkLookupTable>::New();
  std::vector<FlexibleView> flexible;
  std::vector<RigidShapeView> shapes;
  std::vector<vtkSmartPointer<vtkActor>> joints;
  std::unique_ptr<SceneExtras> extras;  // joint axes, rails, ghost, force arrows
  SceneLabels labels;  // title, legend, stamps, colour bar (scene_labels.h)
  std::unique_ptr<WorldTriad> triad;  // null without options.world_triad
  // Layer 1, drawn over the bodies with the same camera: the reaction arrows and the world
  // triad (which a ground plane nearer the eye would otherwise hide); null without either.
  vtkSmartPointer<vtkRenderer> overlay;
  double umax = 0.0;
  LengthUnit unit;        // of the colour bar and the coloured values (stress: MPa)
  double per_unit = 1.0;  // coloured value = metres x per_unit
  std::vector<std::optional<StressTrack>> stresses;  // per body, with --color von_mises
  double follow_distance = 1.0;
  Eigen::Vector3d direction;
  vtkSmartPointer<vtkActor> ground;  // null with --no-ground
  Eigen::Vector3d ground_point = Eigen::Vector3d::Zero();

  // Per body (results.bodies order): the rigid fits through the joint nodes holding it at each
  // time, with those joints' names (relative_deflection.h; no span for a rigid body, no anchor
  // for a flexible one without joints).
  std::vector<TimedRigidFit> fits;

  Impl(const Results& r, const RenderOptions& o) : results(r), options(o), labels(renderer, o) {
    for (const BodyTrack& body : results.bodies) fits.push_back(timed_rigid_fit(results, body));
  }

  // Ground positions of a flexible body's nodes, the elastic displacement relative to the
  // rigid fit through its joint nodes scaled (the fitted rigid part at true size, so joints
  // stay connected), and that relative displacement's magnitudes [m].
  void deformed_nodes(std::size_t b, const BodyState& state, double t, RowMatrix3d& x_W,
                      Eigen::VectorXd& u_norm) const {
    const BodyTrack& body = results.bodies[b];
    const RowMatrix3d u = elastic_displacements(body.mesh, state);
    const RowMatrix3d u_rel = relative_displacements(fits[b].at(t).basis, body.mesh.nodes, u);
    const Eigen::Matrix3d R = state.orientation.toRotationMatrix();
    x_W = ((body.mesh.nodes + (u - u_rel) + options.scale * u_rel) * R.transpose()).rowwise() +
          state.position.transpose();
    u_norm = u_rel.rowwise().norm();
  }

  // One sample of the motion into `motion` (scene_layout.h): the boxes of everything drawn in
  // camera and ground axes, and a box about each part in its own axes (a body's deformed mesh,
  // each primitive; a joint point). Raises umax to the sample's largest |u_rel|. Returns the
  // ground box.
  Bounds add_sample(const SampleBracket& at, const CameraAxes& axes, MotionExtent& motion) {
    CameraBox& view = motion.view_boxes.emplace_back();
    Bounds ground;
    auto add = [&](const Eigen::Vector3d& p, double r) {
      ground.add(p, r);
      view.add(axes.of(p), r);
    };
    auto add_part = [&](const CameraBox& box_B, const Eigen::Vector3d& p, const Eigen::Matrix3d& R) {
      const std::vector<Eigen::Vector3d> corners = box_B.corners();
      PartCorners& part = motion.parts_C.emplace_back();
      for (std::size_t k = 0; k < part.size(); ++k) part[k] = axes.of(p + R * corners[k]);
    };
    for (std::size_t index = 0; index < results.bodies.size(); ++index) {
      const BodyTrack& body = results.bodies[index];
      const BodyState state = body_state(body, at);
      const Eigen::Matrix3d R = state.orientation.toRotationMatrix();
      for (const Shape& shape : body.shapes) {
        add(state.position + R * shape.offset_position, shape_radius(shape));
        add_part(shape_box(shape), state.position + R * shape.offset_position,
                 R * shape.offset_orientation.toRotationMatrix());
      }
      if (body.flexible) {
        RowMatrix3d x_W;
        Eigen::VectorXd u_norm;
        deformed_nodes(index, state, at.t, x_W, u_norm);
        if (u_norm.size() > 0) umax = std::max(umax, u_norm.maxCoeff());
        CameraBox box_B;  // the deformed mesh in body axes
        for (Eigen::Index k = 0; k < x_W.rows(); ++k) {
          add(x_W.row(k).transpose(), body.mesh.beam_radius);
          box_B.add(R.transpose() * (x_W.row(k).transpose() - state.position), body.mesh.beam_radius);
        }
        if (!box_B.empty()) add_part(box_B, state.position, R);
      }
      if (body.shapes.empty() && !body.flexible) {
        add(state.position, 0.0);
        add_part(point_box(), state.position, R);
      }
    }
    for (const JointTrack& joint : results.joints) {
      add(joint_position(joint, at), 0.0);
      add_part(point_box(), joint_position(joint, at), Eigen::Matrix3d::Identity());
    }
    motion.ground_boxes.push_back(ground);
    return ground;
  }

  // The joint glyphs and rails at each sample (scene_extras.h) into the motion's boxes and parts.
  void add_glyphs(const std::vector<SampleBracket>& samples, const CameraAxes& axes, MotionExtent& motion) {
    for (std::size_t k = 0; k < samples.size(); ++k) {
      extras->update(samples[k]);
      const std::vector<Eigen::Vector3d> corners = extras->glyph_corners();  // 8 per glyph
      for (std::size_t c = 0; c < corners.size(); ++c) {
        motion.view_boxes[k].add(axes.of(corners[c]));
        motion.ground_boxes[k].add(corners[c]);
        if (c % 8 == 0) motion.parts_C.emplace_back();
        motion.parts_C.back()[c % 8] = axes.of(corners[c]);
      }
    }
  }

  bool by_stress() const { return options.color == ColorBy::kVonMises; }

  // Colour by stress: the range is the largest recorded element stress in [t0, t1] [MPa].
  void read_stress_range(double t0, double t1) {
    stresses = read_stress_tracks(results);
    if (std::none_of(stresses.begin(), stresses.end(), [](const auto& t) { return t.has_value(); })) {
      throw InputError("--color von_mises: expected a results file with stress output ('stress: {elements: "
                       "all}' on a flexible body of the case, docs/stress-recovery.md), got none in '" +
                       results.file.string() + "'");
    }
    umax = 0.0;
    for (const std::optional<StressTrack>& track : stresses) {
      if (!track) continue;
      for (Eigen::Index row = 0; row < track->time.size(); ++row) {
        const double t = track->time(row);
        const bool inside = t >= t0 && t <= t1;
        if (inside || row == track->row_at(t0)) umax = std::max(umax, track->equivalent.row(row).maxCoeff() / 1e6);
      }
    }
  }

  // The lookup table over [0, umax] in the unit its largest value reads best in (mm for
  // millimetres; stresses in MPa).
  void set_color_range() {
    if (umax <= 0.0) umax = 1.0;
    unit = by_stress() ? LengthUnit{"MPa", 1.0} : length_unit_for(umax);
    per_unit = unit.per_metre;
    fill_lookup_table(lut, options.color_map, per_unit * umax);
  }

  // Bodies: meshes, primitives; joints as small spheres, sized by the scene's radius [m].
  void add_bodies_and_joints(double radius) {
    for (std::size_t b = 0; b < results.bodies.size(); ++b) {
      const BodyTrack& body = results.bodies[b];
      const StressTrack* stress = b < stresses.size() && stresses[b] ? &*stresses[b] : nullptr;
      if (body.flexible) {
        const FlexibleColoring coloring{lut, per_unit * umax, by_stress()};
        flexible.push_back(add_flexible_view(renderer, body, b, stress, coloring));
      }
      for (const Shape& shape : body.shapes) add_shape(body, shape);
    }
    for (std::size_t j = 0; j < results.joints.size(); ++j) {
      auto sphere = vtkSmartPointer<vtkSphereSource>::New();
      sphere->SetRadius(0.015 * radius);
      sphere->SetThetaResolution(16);
      sphere->SetPhiResolution(8);
      auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
      mapper->SetInputConnection(sphere->GetOutputPort());
      auto actor = vtkSmartPointer<vtkActor>::New();
      actor->SetMapper(mapper);
      actor->GetProperty()->SetColor(kJointColor[0], kJointColor[1], kJointColor[2]);
      renderer->AddActor(actor);
      joints.push_back(actor);
    }
  }

  void add_shape(const BodyTrack& body, const Shape& shape) {
    auto actor = vtkSmartPointer<vtkActor>::New();
    actor->SetMapper(primitive_mapper(shape));
    actor->GetProperty()->SetColor(shape.color.x(), shape.color.y(), shape.color.z());
    actor->GetProperty()->SetSpecular(0.3);
    actor->SetUserMatrix(vtkSmartPointer<vtkMatrix4x4>::New());
    renderer->AddActor(actor);
    shapes.push_back({&body, &shape, actor});
  }

  // Ground: a plane under the whole motion (`all`, of radius `radius`), +z up.
  void add_ground(const Bounds& all, double radius) {
    auto plane = vtkSmartPointer<vtkPlaneSource>::New();
    const Eigen::Vector3d c = all.center();
    const double half = 1.5 * radius;
    const double z = all.lo.z() - 0.02 * radius;
    plane->SetOrigin(c.x() - half, c.y() - half, z);
    plane->SetPoint1(c.x() + half, c.y() - half, z);
    plane->SetPoint2(c.x() - half, c.y() + half, z);
    auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
    mapper->SetInputConnection(plane->GetOutputPort());
    ground = vtkSmartPointer<vtkActor>::New();
    ground->SetMapper(mapper);
    ground->GetProperty()->SetColor(kGroundColor[0], kGroundColor[1], kGroundColor[2]);
    ground->GetProperty()->SetAmbient(0.3);
    renderer->AddActor(ground);
    ground_point = Eigen::Vector3d(c.x(), c.y(), z);
  }

  // Colour bar with units, only when something is coloured.
  void add_color_bar() {
    if (flexible.empty()) return;
    bool relative = false;
    for (const TimedRigidFit& fit : fits) relative = relative || fit.any_anchor();
    const std::string title = by_stress() ? "von Mises" : relative ? "|u rel.|" : "|u|";
    labels.add_color_bar(lut, title + " [" + unit.name + "]");
  }

  // Background, lighting; VTK's FXAA pass only when asked for (the default FXAA runs on the
  // read-back frame: far cheaper in software, docs/benchmarks.md). No multisampling.
  void set_background_and_lights() {
    renderer->SetBackground(kBackgroundColor[0], kBackgroundColor[1], kBackgroundColor[2]);
    auto lights = vtkSmartPointer<vtkLightKit>::New();
    lights->AddLightsToRenderer(renderer);
    if (overlay) lights->AddLightsToRenderer(overlay);  // the triad's arrows lit as the bodies
    renderer->SetUseFXAA(options.anti_aliasing == AntiAliasing::kGlFxaa);
  }

  // Camera at `distance` from `focal` along the preset's direction; the clipping range is
  // reset by update().
  void place_camera(const Eigen::Vector3d& focal, double distance) {
    vtkCamera* camera = renderer->GetActiveCamera();
    const Eigen::Vector3d eye = focal + distance * direction;
    // Up is ground z, or y when looking along z.
    const Eigen::Vector3d up = up_hint(direction);
    camera->SetViewAngle(kViewAngleDeg);
    camera->SetFocalPoint(focal.x(), focal.y(), focal.z());
    camera->SetPosition(eye.x(), eye.y(), eye.z());
    camera->SetViewUp(up.x(), up.y(), up.z());
  }
};

Scene::Scene(const Results& results, const RenderOptions& options, double t0, double t1)
    : impl_(std::make_unique<Impl>(results, options)) {
  Impl& s = *impl_;
  LIMBER_DEMAND(results.sample_count() >= 1);
  s.direction = Eigen::Vector3d(view_direction(options).data());
  const CameraAxes axes = camera_axes(s.direction, up_hint(s.direction));

  // The motion over the samples in [t0, t1] (at least one): the camera's extent and the colour
  // range.
  const std::vector<SampleBracket> samples = samples_in(results.time, t0, t1);
  MotionExtent motion;
  Bounds all;
  double frame_radius = 0.0;
  for (const SampleBracket& at : samples) {
    const Bounds b = s.add_sample(at, axes, motion);
    if (b.empty()) continue;
    all.add(b.lo);
    all.add(b.hi);
    frame_radius = std::max(frame_radius, b.radius());
  }
  if (s.by_stress()) s.read_stress_range(t0, t1);
  if (all.empty()) all.add(Eigen::Vector3d::Zero(), 1.0);
  const double radius = std::max(all.radius(), 1e-6);
  frame_radius = std::max(frame_radius, 1e-6);
  s.set_color_range();

  // Actors: bodies, joints, their glyphs (which the camera also holds), ground.
  s.add_bodies_and_joints(radius);
  s.extras = std::make_unique<SceneExtras>(results, options, s.renderer, radius, t0, t1);
  s.labels.add_texts(s.extras->texts());
  s.add_glyphs(samples, axes, motion);
  if (options.ground) s.add_ground(all, radius);
  // The world triad, also the length scale, in the overlay layer: sized and placed with the
  // camera (a quarter of the motion's radius with --follow).
  s.overlay = s.extras->overlay();
  if (options.world_triad) {
    if (!s.overlay) s.overlay = overlay_layer(s.renderer);
    s.triad = std::make_unique<WorldTriad>(s.overlay, round_length(0.25 * radius),
                                           std::max(kMinFontSize, options.height / 45));
    s.labels.add_texts(s.triad->labels());
  }

  // Texts: colour bar, title, deformation legend, time and event stamps (scene_labels.h).
  s.add_color_bar();
  s.labels.add_title_legend_and_stamps(results, s.fits, t0);
  s.set_background_and_lights();

  // Camera: a fixed one fits the whole motion and puts the legend and triad where the motion
  // leaves room (scene_layout.h); a follow one fits the largest single frame, the triad beside
  // the motion's lowest corner. The scene is put at t0 first: clipping ranges read the actors'
  // bounds.
  const double fit = 1.0 / std::sin(0.5 * kViewAngleDeg * M_PI / 180.0);
  s.follow_distance = 1.05 * fit * frame_radius;
  if (options.follow) {
    s.place_camera(all.center(), 1.05 * fit * radius);
    if (s.triad) s.triad->place(all.lo - Eigen::Vector3d(0.75 * s.triad->length(), 0.0, 0.0));
  } else {
    fit_camera_and_overlays(s.renderer, motion, axes, options, s.labels, s.triad.get());
  }
  // The ground is flat and matte under the light kit's directional lights, and the camera's
  // direction is fixed: one colour, drawn unlit (flat_shading.h; the same pixels, cheaper).
  if (s.ground) {
    const std::optional<Eigen::Vector3d> color = flat_surface_color(
        s.renderer, s.ground->GetProperty(), s.ground_point, Eigen::Vector3d::UnitZ());
    if (color) set_unlit_color(s.ground->GetProperty(), *color);
  }
  update(t0);
}

Scene::~Scene() = default;

vtkRenderer* Scene::renderer() const { return impl_->renderer; }

vtkRenderer* Scene::overlay_renderer() const { return impl_->overlay; }

const SceneExtras& Scene::extras() const { return *impl_->extras; }

double Scene::color_range_max() const { return impl_->umax; }

std::vector<PixelBox> Scene::overlay_boxes() const { return impl_->labels.overlay_boxes(); }

std::vector<Scene::DrawnText> Scene::drawn_texts() const { return impl_->labels.drawn_texts(); }

const std::string& Scene::color_unit() const { return impl_->unit.name; }

void Scene::update(double t) {
  Impl& s = *impl_;
  const SampleBracket at = bracket(s.results.time, t);

  // Flexible bodies: deformed nodes in ground and |u| per node.
  RowMatrix3d x_W;
  Eigen::VectorXd u_norm;
  for (FlexibleView& view : s.flexible) {
    const BodyState state = body_state(*view.body, at);
    s.deformed_nodes(view.index, state, at.t, x_W, u_norm);
    update_flexible_view(view, state, x_W, u_norm, s.per_unit, t);
  }

  // Rigid primitives: body pose times shape offset times primitive axes.
  for (RigidShapeView& view : s.shapes) {
    const BodyState state = body_state(*view.body, at);
    const Eigen::Matrix3d R = state.orientation.toRotationMatrix();
    const Eigen::Matrix3d R_shape =
        R * view.shape->offset_orientation.toRotationMatrix() * primitive_axes(*view.shape);
    set_pose(view.actor->GetUserMatrix(), state.position + R * view.shape->offset_position,
             R_shape);
    view.actor->Modified();
  }

  // Joints.
  for (std::size_t j = 0; j < s.joints.size(); ++j) {
    const Eigen::Vector3d p = joint_position(s.results.joints[j], at);
    s.joints[j]->SetPosition(p.x(), p.y(), p.z());
    // A released hold-down is gone.
    s.joints[j]->SetVisibility(s.results.joints[j].held_at(at.t) ? 1 : 0);
  }
  s.extras->update(at);

  // Time and event stamps and, for a follow camera, the centroid of the body frames.
  s.labels.update(s.results, t);
  if (s.options.follow && !s.results.bodies.empty()) {
    Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
    for (const BodyTrack& body : s.results.bodies) centroid += body_state(body, at).position;
    s.place_camera(centroid / static_cast<double>(s.results.bodies.size()), s.follow_distance);
  }
  // The clipping range holds the bodies and the overlay's arrows and triad (one camera for both).
  double bounds[6];
  s.renderer->ComputeVisiblePropBounds(bounds);
  if (vtkRenderer* overlay = s.overlay) {
    double arrows[6];
    overlay->ComputeVisiblePropBounds(arrows);
    for (int k = 0; k < 6; k += 2) {
      bounds[k] = std::min(bounds[k], arrows[k]);
      bounds[k + 1] = std::max(bounds[k + 1], arrows[k + 1]);
    }
  }
  s.renderer->ResetCameraClippingRange(bounds);
}

}  // namespace limber::render
