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
#include "world_triad.h"

#include <vtkActor.h>
#include <vtkBillboardTextActor3D.h>
#include <vtkCamera.h>
#include <vtkCubeSource.h>
#include <vtkCylinderSource.h>
#include <vtkLightKit.h>
#include <vtkLookupTable.h>
#include <vtkMatrix4x4.h>
#include <vtkPlaneSource.h>
#include <vtkPolyDataMapper.h>
#include <vtkPropCollection.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkSphereSource.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

namespace limber::render {
namespace {

constexpr double kViewAngleDeg = 30.0;

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

// Draws the 3D labels (billboard texts) as opaque geometry after every other prop: a
// translucent prop makes VTK 9.1 run its order-independent translucency pass, several
// full-frame passes that cost llvmpipe about 11 ms of CPU per 1280 x 720 frame
// (docs/benchmarks.md). Drawn last, a label's anti-aliased edges blend over everything behind
// it, as the translucent pass blends them: the same pixels.
void draw_labels_last_and_opaque(vtkRenderer* renderer) {
  std::vector<vtkBillboardTextActor3D*> labels;
  vtkPropCollection* props = renderer->GetViewProps();
  vtkCollectionSimpleIterator it;
  props->InitTraversal(it);
  while (vtkProp* prop = props->GetNextProp(it)) {
    if (auto* label = vtkBillboardTextActor3D::SafeDownCast(prop)) labels.push_back(label);
  }
  for (vtkBillboardTextActor3D* label : labels) {
    label->ForceOpaqueOn();
    vtkSmartPointer<vtkBillboardTextActor3D> keep = label;  // alive while out of the renderer
    renderer->RemoveViewProp(label);
    renderer->AddViewProp(label);
  }
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
  double umax = 0.0;
  LengthUnit unit;        // of the colour bar and the coloured values (stress: MPa)
  double per_unit = 1.0;  // coloured value = metres x per_unit
  std::vector<std::optional<StressTrack>> stresses;  // per body, with --color von_mises
  double follow_distance = 1.0;
  Eigen::Vector3d direction;
  vtkSmartPointer<vtkActor> ground;  // null with --no-ground
  Eigen::Vector3d ground_point = Eigen::Vector3d::Zero();

  // Per body (results.bodies order): the rigid fit through its joint nodes (relative_deflection.h;
  // empty for rigid bodies and flexible ones without joints) and those joints' names.
  std::vector<RigidFitBasis> fits;
  std::vector<std::vector<std::string>> fit_joints;

  Impl(const Results& r, const RenderOptions& o) : results(r), options(o), labels(renderer, o) {
    for (const BodyTrack& body : results.bodies) {
      std::vector<std::string> names;
      const std::vector<Eigen::Index> anchors = joint_nodes(results, body, &names);
      fits.push_back(rigid_fit_basis(body.mesh.nodes, anchors));
      fit_joints.push_back(std::move(names));
    }
  }

  // Ground positions of a flexible body's nodes, the elastic displacement relative to the
  // rigid fit through its joint nodes scaled (the fitted rigid part at true size, so joints
  // stay connected), and that relative displacement's magnitudes [m].
  void deformed_nodes(std::size_t b, const BodyState& state, RowMatrix3d& x_W,
                      Eigen::VectorXd& u_norm) const {
    const BodyTrack& body = results.bodies[b];
    const RowMatrix3d u = elastic_displacements(body.mesh, state);
    const RowMatrix3d u_rel = relative_displacements(fits[b], body.mesh.nodes, u);
    const Eigen::Matrix3d R = state.orientation.toRotationMatrix();
    x_W = ((body.mesh.nodes + (u - u_rel) + options.scale * u_rel) * R.transpose()).rowwise() +
          state.position.transpose();
    u_norm = u_rel.rowwise().norm();
  }

  // Bounds of everything drawn at one time, in ground and in camera axes (`view`); and, in
  // `hull_W` (ground), the corners of a box about each body in its own axes (its deformed mesh,
  // each primitive) and the joints: points whose convex hull holds the frame's content, tighter
  // than an axis-aligned box when bodies lie askew (a deployed wing seen from iso).
  Bounds bounds_at(const SampleBracket& at, const CameraAxes& axes, CameraBox& view,
                   std::vector<Eigen::Vector3d>& hull_W) const {
    struct {
      Bounds ground;
      CameraBox* view;
      const CameraAxes* axes;
      void add(const Eigen::Vector3d& p, double r = 0.0) {
        ground.add(p, r);
        view->add(axes->of(p), r);
      }
    } b{Bounds{}, &view, &axes};
    for (std::size_t index = 0; index < results.bodies.size(); ++index) {
      const BodyTrack& body = results.bodies[index];
      const BodyState state = body_state(body, at);
      const Eigen::Matrix3d R = state.orientation.toRotationMatrix();
      for (const Shape& shape : body.shapes) {
        b.add(state.position + R * shape.offset_position, shape_radius(shape));
        add_shape_corners(shape, state.position, R, hull_W);
      }
      if (body.flexible) {
        RowMatrix3d x_W;
        Eigen::VectorXd u_norm;
        deformed_nodes(index, state, x_W, u_norm);
        CameraBox box_B;  // the deformed mesh in body axes
        for (Eigen::Index k = 0; k < x_W.rows(); ++k) {
          b.add(x_W.row(k).transpose(), body.mesh.beam_radius);
          box_B.add(R.transpose() * (x_W.row(k).transpose() - state.position), body.mesh.beam_radius);
        }
        for (const Eigen::Vector3d& corner : box_B.corners()) hull_W.push_back(state.position + R * corner);
      }
      if (body.shapes.empty() && !body.flexible) {
        b.add(state.position);
        hull_W.push_back(state.position);
      }
    }
    for (const JointTrack& joint : results.joints) {
      b.add(joint_position(joint, at));
      hull_W.push_back(joint_position(joint, at));
    }
    return b.ground;
  }

  // The 8 corners of a primitive's box in its own axes (a cylinder's about its axis z, a
  // sphere's cube), for a body at (p, R), into `hull_W`.
  static void add_shape_corners(const Shape& shape, const Eigen::Vector3d& p, const Eigen::Matrix3d& R,
                                std::vector<Eigen::Vector3d>& hull_W) {
    const Eigen::Vector3d half = shape.type == Shape::Type::kBox        ? Eigen::Vector3d(0.5 * shape.size)
                                 : shape.type == Shape::Type::kCylinder ? Eigen::Vector3d(shape.size.x(), shape.size.x(),
                                                                                          0.5 * shape.size.z())
                                                                        : Eigen::Vector3d::Constant(shape.size.x());
    const Eigen::Matrix3d R_shape = R * shape.offset_orientation.toRotationMatrix();
    CameraBox box;
    box.lo = -half;
    box.hi = half;
    for (const Eigen::Vector3d& corner : box.corners()) {
      hull_W.push_back(p + R * shape.offset_position + R_shape * corner);
    }
  }

  bool by_stress() const { return options.color == ColorBy::kVonMises; }

  void add_shape(const BodyTrack& body, const Shape& shape) {
    auto actor = vtkSmartPointer<vtkActor>::New();
    actor->SetMapper(primitive_mapper(shape));
    actor->GetProperty()->SetColor(shape.color.x(), shape.color.y(), shape.color.z());
    actor->GetProperty()->SetSpecular(0.3);
    actor->SetUserMatrix(vtkSmartPointer<vtkMatrix4x4>::New());
    renderer->AddActor(actor);
    shapes.push_back({&body, &shape, actor});
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

  // Colour range and camera extent from the samples in [t0, t1] (at least one sample).
  Bounds all;
  double frame_radius = 0.0;
  // Per sample, two boxes holding what is drawn, in camera and in ground axes: the fixed
  // camera fits the tighter of their hulls (a wing along ground y is tight in ground axes).
  std::vector<CameraBox> frame_boxes, ground_boxes;
  std::vector<Eigen::Vector3d> body_hull_W;  // per sample, boxes about each body (bounds_at)
  std::vector<SampleBracket> samples;
  for (Eigen::Index i = 0; i < results.sample_count(); ++i) {
    if (results.time(i) >= t0 && results.time(i) <= t1) samples.push_back({i, 0.0});
  }
  if (samples.empty()) samples.push_back(bracket(results.time, t0));
  for (const SampleBracket& at : samples) {
    CameraBox& view = frame_boxes.emplace_back();
    const Bounds b = s.bounds_at(at, axes, view, body_hull_W);
    ground_boxes.push_back(b);
    if (b.empty()) continue;
    all.add(b.lo);
    all.add(b.hi);
    frame_radius = std::max(frame_radius, b.radius());
    for (std::size_t b = 0; b < results.bodies.size(); ++b) {
      const BodyTrack& body = results.bodies[b];
      if (!body.flexible) continue;
      const RowMatrix3d u = relative_displacements(
          s.fits[b], body.mesh.nodes, elastic_displacements(body.mesh, body_state(body, at)));
      if (u.rows() > 0) s.umax = std::max(s.umax, u.rowwise().norm().maxCoeff());
    }
  }
  // Colour by stress: the range is the largest recorded element stress in [t0, t1] [MPa].
  if (s.by_stress()) {
    s.stresses = read_stress_tracks(results);
    if (std::none_of(s.stresses.begin(), s.stresses.end(), [](const auto& t) { return t.has_value(); })) {
      throw InputError("--color von_mises: expected a results file with stress output ('stress: {elements: "
                       "all}' on a flexible body of the case, docs/stress-recovery.md), got none in '" +
                       results.file.string() + "'");
    }
    s.umax = 0.0;
    for (const std::optional<StressTrack>& track : s.stresses) {
      if (!track) continue;
      for (Eigen::Index row = 0; row < track->time.size(); ++row) {
        const double t = track->time(row);
        const bool inside = t >= t0 && t <= t1;
        if (inside || row == track->row_at(t0)) s.umax = std::max(s.umax, track->equivalent.row(row).maxCoeff() / 1e6);
      }
    }
  }
  if (all.empty()) all.add(Eigen::Vector3d::Zero(), 1.0);
  // The world triad (also the length scale) beside the motion, below its lowest corner, inside
  // the camera's fit: close, so that it takes little of the frame from the motion.
  const double triad_length = round_length(0.25 * std::max(all.radius(), 1e-6));
  const Eigen::Vector3d triad_origin =
      all.lo - Eigen::Vector3d(0.75 * triad_length, 0.0, 0.0);
  if (options.world_triad) {
    CameraBox& view = frame_boxes.emplace_back();
    CameraBox& ground = ground_boxes.emplace_back();
    for (const Eigen::Vector3d& p : {triad_origin, Eigen::Vector3d(triad_origin + 1.3 * triad_length * Eigen::Vector3d::Ones())}) {
      all.add(p, 0.25 * triad_length);
      view.add(axes.of(p), 0.25 * triad_length);
      ground.add(p, 0.25 * triad_length);
      CameraBox around;
      around.add(p, 0.25 * triad_length);
      for (const Eigen::Vector3d& corner : around.corners()) body_hull_W.push_back(corner);
    }
  }
  const double radius = std::max(all.radius(), 1e-6);
  frame_radius = std::max(frame_radius, 1e-6);
  const double range_max = s.umax > 0.0 ? s.umax : 1.0;
  s.umax = range_max;
  // Lengths in the unit their largest value reads best in (mm for millimetres); stresses in MPa.
  s.unit = s.by_stress() ? LengthUnit{"MPa", 1.0} : length_unit_for(range_max);
  s.per_unit = s.unit.per_metre;
  fill_lookup_table(s.lut, options.color_map, s.per_unit * range_max);

  // Bodies: meshes, primitives; joints as small spheres.
  for (std::size_t b = 0; b < results.bodies.size(); ++b) {
    const BodyTrack& body = results.bodies[b];
    const StressTrack* stress = b < s.stresses.size() && s.stresses[b] ? &*s.stresses[b] : nullptr;
    if (body.flexible) {
      const FlexibleColoring coloring{s.lut, s.per_unit * s.umax, s.by_stress()};
      s.flexible.push_back(add_flexible_view(s.renderer, body, b, stress, coloring));
    }
    for (const Shape& shape : body.shapes) s.add_shape(body, shape);
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
    s.renderer->AddActor(actor);
    s.joints.push_back(actor);
  }

  // Joint axes and rails, ghost outlines, force arrows (scene_extras.h).
  s.extras = std::make_unique<SceneExtras>(results, options, s.renderer, radius, t0, t1);
  s.labels.add_texts(s.extras->texts());
  for (std::size_t k = 0; k < samples.size(); ++k) {
    s.extras->update(samples[k]);
    for (const Eigen::Vector3d& corner : s.extras->glyph_corners()) {
      frame_boxes[k].add(axes.of(corner));
      ground_boxes[k].add(corner);
      body_hull_W.push_back(corner);
    }
  }

  // Ground: a plane under the whole motion, +z up.
  if (options.ground) {
    auto plane = vtkSmartPointer<vtkPlaneSource>::New();
    const Eigen::Vector3d c = all.center();
    const double half = 1.5 * radius;
    const double z = all.lo.z() - 0.02 * radius;
    plane->SetOrigin(c.x() - half, c.y() - half, z);
    plane->SetPoint1(c.x() + half, c.y() - half, z);
    plane->SetPoint2(c.x() - half, c.y() + half, z);
    auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
    mapper->SetInputConnection(plane->GetOutputPort());
    auto actor = vtkSmartPointer<vtkActor>::New();
    actor->SetMapper(mapper);
    actor->GetProperty()->SetColor(kGroundColor[0], kGroundColor[1], kGroundColor[2]);
    actor->GetProperty()->SetAmbient(0.3);
    s.renderer->AddActor(actor);
    s.ground = actor;
    s.ground_point = Eigen::Vector3d(c.x(), c.y(), z);
  }

  if (options.world_triad) {
    add_world_triad(s.renderer, triad_origin, triad_length, std::max(kMinFontSize, options.height / 45));
  }

  // Colour bar with units, only when something is coloured.
  if (!s.flexible.empty()) {
    bool relative = false;
    for (const RigidFitBasis& fit : s.fits) relative = relative || !fit.anchors.empty();
    const std::string title = s.by_stress() ? "von Mises" : relative ? "|u rel.|" : "|u|";
    s.labels.add_color_bar(s.lut, title + " [" + s.unit.name + "]");
  }

  // Title, deformation legend, time and event stamps (scene_labels.h).
  const int font = s.labels.stamp_font();
  const double content_top = s.labels.add_title_legend_and_stamps(results, s.fits, s.fit_joints);

  // Background, lighting; VTK's FXAA pass only when asked for (the default FXAA runs on the
  // read-back frame: far cheaper in software, docs/benchmarks.md). No multisampling.
  s.renderer->SetBackground(kBackgroundColor[0], kBackgroundColor[1], kBackgroundColor[2]);
  auto lights = vtkSmartPointer<vtkLightKit>::New();
  lights->AddLightsToRenderer(s.renderer);
  s.renderer->SetUseFXAA(options.anti_aliasing == AntiAliasing::kGlFxaa);

  // Camera: a fixed one fits the whole motion, a follow one fits the largest single frame.
  // The scene is put at t0 first: clipping ranges read the actors' bounds.
  const double fit = 1.0 / std::sin(0.5 * kViewAngleDeg * M_PI / 180.0);
  s.follow_distance = 1.05 * fit * frame_radius;
  if (options.follow) {
    s.place_camera(all.center(), 1.05 * fit * radius);
  } else {
    // The whole motion inside the frame less its texts: left of the colour bar, above the
    // time and event stamps, under the title and legend (camera_fit.h).
    ViewWindow window;
    window.x0 = 0.02;
    window.x1 = s.labels.has_color_bar() ? kColorBarBox[0] - 0.02 : 0.98;
    window.y0 = options.time_stamp ? 0.03 + 1.6 * font / options.height : 0.03;
    if (options.forces) window.y0 = 0.17;  // above the arrow legends (scene_extras.h)
    window.y1 = content_top;
    // Three hulls of the whole motion, each holding all of it: the corners of each frame's box
    // in camera axes, in ground axes, and of the boxes about each body in its own axes; the
    // camera fits the tightest (nearest eye).
    std::vector<Eigen::Vector3d> view_hull, ground_hull, body_hull;
    for (const CameraBox& box : frame_boxes) {
      for (const Eigen::Vector3d& p : box.corners()) view_hull.push_back(p);
    }
    for (const CameraBox& box : ground_boxes) {
      for (const Eigen::Vector3d& p : box.corners()) ground_hull.push_back(axes.of(p));
    }
    for (const Eigen::Vector3d& p : body_hull_W) body_hull.push_back(axes.of(p));
    const double aspect = static_cast<double>(options.width) / options.height;
    CameraPlacement placement = fit_camera(view_hull, axes, kViewAngleDeg, aspect, window);
    for (const std::vector<Eigen::Vector3d>* hull : {&ground_hull, &body_hull}) {
      const CameraPlacement other = fit_camera(*hull, axes, kViewAngleDeg, aspect, window);
      if (other.eye_back < placement.eye_back) placement = other;
    }
    vtkCamera* camera = s.renderer->GetActiveCamera();
    camera->SetViewAngle(kViewAngleDeg);
    camera->SetPosition(placement.eye.data());
    camera->SetFocalPoint(placement.focal.data());
    camera->SetViewUp(axes.up.data());
    camera->SetWindowCenter(-placement.axis_at.x(), -placement.axis_at.y());
  }
  // The ground is flat and matte under the light kit's directional lights, and the camera's
  // direction is fixed: one colour, drawn unlit (flat_shading.h; the same pixels, cheaper).
  if (s.ground) {
    const std::optional<Eigen::Vector3d> color = flat_surface_color(
        s.renderer, s.ground->GetProperty(), s.ground_point, Eigen::Vector3d::UnitZ());
    if (color) set_unlit_color(s.ground->GetProperty(), *color);
  }
  draw_labels_last_and_opaque(s.renderer);
  update(t0);
}

Scene::~Scene() = default;

vtkRenderer* Scene::renderer() const { return impl_->renderer; }

vtkRenderer* Scene::overlay_renderer() const { return impl_->extras->overlay(); }

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
    s.deformed_nodes(view.index, state, x_W, u_norm);
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
  // The clipping range holds the bodies and the overlay's arrows (one camera for both).
  double bounds[6];
  s.renderer->ComputeVisiblePropBounds(bounds);
  if (vtkRenderer* overlay = s.extras->overlay()) {
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
