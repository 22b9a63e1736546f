#include "scene.h"

#include "beam_solids.h"
#include "body_pose.h"
#include "camera_fit.h"
#include "color_map.h"
#include "event_stamp.h"
#include "length_unit.h"
#include "flat_shading.h"
#include "stress_reader.h"
#include "core/error.h"
#include "relative_deflection.h"
#include "scene_extras.h"
#include "world_triad.h"

#include <vtkActor.h>
#include <vtkAlgorithmOutput.h>
#include <vtkBillboardTextActor3D.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCubeSource.h>
#include <vtkCylinderSource.h>
#include <vtkDoubleArray.h>
#include <vtkLightKit.h>
#include <vtkLookupTable.h>
#include <vtkMatrix4x4.h>
#include <vtkPlaneSource.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkPropCollection.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkScalarBarActor.h>
#include <vtkSphereSource.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>
#include <vtkTubeFilter.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
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

// A flexible body: points in ground updated per frame, quads as a surface, lines as tubes.
struct FlexibleView {
  const BodyTrack* body = nullptr;
  std::size_t index = 0;  // in results.bodies
  vtkSmartPointer<vtkPoints> points;
  vtkSmartPointer<vtkDoubleArray> magnitude;
  vtkSmartPointer<vtkPolyData> surface;
  vtkSmartPointer<vtkPolyData> beams;
  // Colouring by stress: the body's stress history (none: drawn in the NaN colour) and the
  // per-cell values of the quads and lines [MPa].
  const StressTrack* stress = nullptr;
  vtkSmartPointer<vtkDoubleArray> quad_stress;
  vtkSmartPointer<vtkDoubleArray> line_stress;
  // Beams as swept sections (beam_solids.h; null for files without them): the surface, per
  // point its node and offset from that node (body frame) and |u|, per cell the stress.
  vtkSmartPointer<vtkPolyData> solids;
  vtkSmartPointer<vtkDoubleArray> solid_magnitude;
  vtkSmartPointer<vtkDoubleArray> solid_stress;
  BeamSolids solid_mesh;
  RowMatrix3d solid_offset_B;
};

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
  vtkSmartPointer<vtkTextActor> time_text = vtkSmartPointer<vtkTextActor>::New();
  vtkSmartPointer<vtkTextActor> event_text = vtkSmartPointer<vtkTextActor>::New();
  double event_hold = 0.0;  // simulated time an event stays stamped [s] (event_stamp.h)
  std::vector<vtkSmartPointer<vtkTextActor>> texts;  // every text drawn (title, note, time)
  vtkSmartPointer<vtkScalarBarActor> bar;            // null without flexible bodies
  int bar_font = 10;                                 // colour bar label size [pixels]
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

  Impl(const Results& r, const RenderOptions& o) : results(r), options(o) {
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

  // Bounds of everything drawn at one time, in ground and in camera axes (`view`).
  Bounds bounds_at(const SampleBracket& at, const CameraAxes& axes, CameraBox& view) const {
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
      }
      if (body.flexible) {
        RowMatrix3d x_W;
        Eigen::VectorXd u_norm;
        deformed_nodes(index, state, x_W, u_norm);
        for (Eigen::Index k = 0; k < x_W.rows(); ++k) {
          b.add(x_W.row(k).transpose(), body.mesh.beam_radius);
        }
      }
      if (body.shapes.empty() && !body.flexible) b.add(state.position);
    }
    for (const JointTrack& joint : results.joints) b.add(joint_position(joint, at));
    return b.ground;
  }

  bool by_stress() const { return options.color == ColorBy::kVonMises; }

  // A per-cell array of `count` values, NaN until the first update.
  static vtkSmartPointer<vtkDoubleArray> cell_values(Eigen::Index count) {
    auto values = vtkSmartPointer<vtkDoubleArray>::New();
    values->SetName("stress_MPa");
    values->SetNumberOfTuples(static_cast<vtkIdType>(count));
    values->Fill(std::numeric_limits<double>::quiet_NaN());
    return values;
  }

  void add_flexible(const BodyTrack& body, std::size_t index, const StressTrack* stress) {
    FlexibleView view;
    view.body = &body;
    view.index = index;
    view.stress = stress;
    const auto nn = static_cast<vtkIdType>(body.mesh.nodes.rows());
    view.points = vtkSmartPointer<vtkPoints>::New();
    view.points->SetDataTypeToDouble();
    view.points->SetNumberOfPoints(nn);
    view.magnitude = vtkSmartPointer<vtkDoubleArray>::New();
    view.magnitude->SetName("displacement_magnitude");
    view.magnitude->SetNumberOfTuples(nn);

    // Shells: one surface of quads, coloured by |u|.
    if (body.mesh.quads.rows() > 0) {
      auto quads = vtkSmartPointer<vtkCellArray>::New();
      for (Eigen::Index e = 0; e < body.mesh.quads.rows(); ++e) {
        const vtkIdType ids[4] = {body.mesh.quads(e, 0), body.mesh.quads(e, 1),
                                  body.mesh.quads(e, 2), body.mesh.quads(e, 3)};
        quads->InsertNextCell(4, ids);
      }
      view.surface = vtkSmartPointer<vtkPolyData>::New();
      view.surface->SetPoints(view.points);
      view.surface->SetPolys(quads);
      view.surface->GetPointData()->SetScalars(view.magnitude);
      if (by_stress()) {
        view.quad_stress = cell_values(body.mesh.quads.rows());
        view.surface->GetCellData()->SetScalars(view.quad_stress);
      }
      add_colored_actor(view.surface, nullptr);
    }

    // Beams: swept sections where the file has them (beam_solids.h), else lines swept into
    // tubes of the mesh's beam radius (plain thick lines without one).
    view.solid_mesh = beam_solids(body.mesh);
    if (view.solid_mesh.cell_count() > 0) {
      add_solids(view);
    } else if (body.mesh.lines.rows() > 0) {
      auto lines = vtkSmartPointer<vtkCellArray>::New();
      for (Eigen::Index e = 0; e < body.mesh.lines.rows(); ++e) {
        const vtkIdType ids[2] = {body.mesh.lines(e, 0), body.mesh.lines(e, 1)};
        lines->InsertNextCell(2, ids);
      }
      view.beams = vtkSmartPointer<vtkPolyData>::New();
      view.beams->SetPoints(view.points);
      view.beams->SetLines(lines);
      view.beams->GetPointData()->SetScalars(view.magnitude);
      if (by_stress()) {
        view.line_stress = cell_values(body.mesh.lines.rows());
        view.beams->GetCellData()->SetScalars(view.line_stress);
      }
      if (body.mesh.beam_radius > 0.0) {
        auto tube = vtkSmartPointer<vtkTubeFilter>::New();
        tube->SetInputData(view.beams);
        tube->SetRadius(body.mesh.beam_radius);
        tube->SetNumberOfSides(12);
        tube->CappingOn();
        add_colored_actor(nullptr, tube->GetOutputPort());
      } else {
        add_colored_actor(view.beams, nullptr)->GetProperty()->SetLineWidth(3.0f);
      }
    }
    flexible.push_back(view);
  }

  // The beams' swept surface: its own points, moved in update() with the nodes they follow.
  void add_solids(FlexibleView& view) {
    const BeamSolids& solids = view.solid_mesh;
    const auto np = static_cast<vtkIdType>(solids.points_B.rows());
    view.solid_offset_B = solids.points_B;
    for (Eigen::Index k = 0; k < solids.points_B.rows(); ++k) {
      view.solid_offset_B.row(k) -= view.body->mesh.nodes.row(solids.node[static_cast<std::size_t>(k)]);
    }
    auto points = vtkSmartPointer<vtkPoints>::New();
    points->SetDataTypeToDouble();
    points->SetNumberOfPoints(np);
    auto cells = vtkSmartPointer<vtkCellArray>::New();
    std::vector<vtkIdType> ids;
    for (int c = 0; c < solids.cell_count(); ++c) {
      ids.assign(solids.connectivity.begin() + solids.cell_offsets[c],
                 solids.connectivity.begin() + solids.cell_offsets[c + 1]);
      cells->InsertNextCell(static_cast<vtkIdType>(ids.size()), ids.data());
    }
    view.solids = vtkSmartPointer<vtkPolyData>::New();
    view.solids->SetPoints(points);
    view.solids->SetPolys(cells);
    view.solid_magnitude = vtkSmartPointer<vtkDoubleArray>::New();
    view.solid_magnitude->SetName("displacement_magnitude");
    view.solid_magnitude->SetNumberOfTuples(np);
    view.solids->GetPointData()->SetScalars(view.solid_magnitude);
    if (by_stress()) {
      view.solid_stress = cell_values(solids.cell_count());
      view.solids->GetCellData()->SetScalars(view.solid_stress);
    }
    add_colored_actor(view.solids, nullptr);
  }

  // An actor coloured through the shared lookup table, from data or a pipeline output.
  vtkSmartPointer<vtkActor> add_colored_actor(vtkPolyData* data, vtkAlgorithmOutput* port) {
    auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
    if (data != nullptr) mapper->SetInputData(data);
    if (port != nullptr) mapper->SetInputConnection(port);
    mapper->SetLookupTable(lut);
    mapper->SetScalarRange(0.0, per_unit * umax);
    // Stresses are per element (cell data, which the tube filter passes on); |u| per node.
    if (by_stress()) mapper->SetScalarModeToUseCellData();
    else mapper->SetScalarModeToUsePointData();
    mapper->ScalarVisibilityOn();
    auto actor = vtkSmartPointer<vtkActor>::New();
    actor->SetMapper(mapper);
    actor->GetProperty()->SetSpecular(0.2);
    renderer->AddActor(actor);
    return actor;
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

  void add_text(const std::string& text, int size, double x, double y, bool right) {
    auto actor = vtkSmartPointer<vtkTextActor>::New();
    actor->SetInput(text.c_str());
    actor->GetTextProperty()->SetFontSize(size);
    actor->GetTextProperty()->SetColor(0.1, 0.1, 0.15);
    if (right) actor->GetTextProperty()->SetJustificationToRight();
    actor->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
    actor->GetPositionCoordinate()->SetValue(x, y);
    renderer->AddViewProp(actor);
    texts.push_back(actor);
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
  std::vector<SampleBracket> samples;
  for (Eigen::Index i = 0; i < results.sample_count(); ++i) {
    if (results.time(i) >= t0 && results.time(i) <= t1) samples.push_back({i, 0.0});
  }
  if (samples.empty()) samples.push_back(bracket(results.time, t0));
  for (const SampleBracket& at : samples) {
    CameraBox& view = frame_boxes.emplace_back();
    const Bounds b = s.bounds_at(at, axes, view);
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
    if (body.flexible) s.add_flexible(body, b, stress);
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
  for (const auto& text : s.extras->texts()) s.texts.push_back(text);
  for (std::size_t k = 0; k < samples.size(); ++k) {
    s.extras->update(samples[k]);
    for (const Eigen::Vector3d& corner : s.extras->glyph_corners()) {
      frame_boxes[k].add(axes.of(corner));
      ground_boxes[k].add(corner);
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
    auto bar = vtkSmartPointer<vtkScalarBarActor>::New();
    bar->SetLookupTable(s.lut);
    bool relative = false;
    for (const RigidFitBasis& fit : s.fits) relative = relative || !fit.anchors.empty();
    const std::string title = s.by_stress() ? "von Mises" : relative ? "|u rel.|" : "|u|";
    bar->SetTitle((title + " [" + s.unit.name + "]").c_str());
    bar->SetLabelFormat("%.3g");
    bar->SetNumberOfLabels(5);
    bar->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
    bar->GetPositionCoordinate()->SetValue(kColorBarBox[0], kColorBarBox[1]);
    bar->SetWidth(kColorBarBox[2]);
    bar->SetHeight(kColorBarBox[3]);
    bar->SetBarRatio(0.3);
    bar->SetTextPositionToSucceedScalarBar();
    bar->UnconstrainedFontSizeOn();
    s.bar_font = std::max(kMinFontSize, options.height / 45);
    // Labels clear of the bar and the title clear of the top label (VTK's defaults let them
    // touch).
    bar->SetTextPad(std::max(4, s.bar_font / 2));
    bar->SetVerticalTitleSeparation(s.bar_font);
    for (vtkTextProperty* text : {bar->GetTitleTextProperty(), bar->GetLabelTextProperty()}) {
      text->SetColor(0.1, 0.1, 0.15);
      text->SetFontSize(s.bar_font);
      text->ShadowOff();
      text->BoldOff();
      text->ItalicOff();
    }
    s.renderer->AddViewProp(bar);
    s.bar = bar;
  }

  // Title, deformation scale note, time stamp.
  const int font = std::max(kMinFontSize, options.height / 36);
  s.add_text(results.title, std::max(kMinFontSize, options.height / 30), 0.02, 0.93, false);
  // What is scaled, and what the colours measure: the elastic displacement relative to a rigid
  // fit through each flexible body's joint nodes (those without joints: relative to their
  // floating frame).
  // Only when some body is fitted: otherwise what is scaled is plain u, as always.
  std::string legend;
  bool fitted = false;
  for (const RigidFitBasis& fit : s.fits) fitted = fitted || !fit.anchors.empty();
  for (std::size_t b = 0; b < results.bodies.size() && fitted; ++b) {
    if (!results.bodies[b].flexible) continue;
    std::string joints;
    for (const std::string& name : s.fit_joints[b]) joints += (joints.empty() ? "" : ", ") + name;
    legend += "\n" + results.bodies[b].name + ": " +
              (joints.empty() ? "u in its floating frame" : "u relative to a rigid fit through " + joints);
  }
  // Under the title, right-aligned: the content is fitted below its last line.
  const int legend_font = std::max(kMinFontSize, options.height / 40);
  double content_top = 0.88;
  if (options.scale != 1.0 || !legend.empty()) {
    char note[64];
    std::snprintf(note, sizeof note, legend.empty() ? "deformation x %g" : "deformation x %g of the elastic displacement u",
                  options.scale);
    constexpr double kLegendTop = 0.905;
    s.add_text(note + legend, legend_font, 0.98, kLegendTop, true);
    s.texts.back()->GetTextProperty()->SetVerticalJustificationToTop();
    // VTK spaces lines by 1.1 font sizes (vtkTextProperty's LineSpacing); 1.25 leaves a gap.
    const auto lines = 1 + std::count(legend.begin(), legend.end(), '\n');
    content_top = kLegendTop - 1.25 * static_cast<double>(lines * legend_font) / options.height;
  }
  s.time_text->GetTextProperty()->SetFontSize(font);
  s.time_text->GetTextProperty()->SetColor(0.1, 0.1, 0.15);
  s.time_text->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
  s.time_text->GetPositionCoordinate()->SetValue(0.02, 0.03);
  if (options.time_stamp) {
    s.renderer->AddViewProp(s.time_text);
    s.texts.push_back(s.time_text);
  }
  // Hinge events, right of the time stamp, dark red (event_stamp.h).
  s.event_hold = event_hold(options.fps, options.playback_fps);
  if (options.time_stamp && !results.events.empty()) {
    s.event_text->GetTextProperty()->SetFontSize(font);
    s.event_text->GetTextProperty()->SetColor(0.6, 0.05, 0.05);
    s.event_text->GetTextProperty()->BoldOn();
    s.event_text->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
    s.event_text->GetPositionCoordinate()->SetValue(0.36, 0.03);
    s.renderer->AddViewProp(s.event_text);
    s.texts.push_back(s.event_text);
  }

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
    window.x1 = s.bar ? kColorBarBox[0] - 0.02 : 0.98;
    window.y0 = options.time_stamp ? 0.03 + 1.6 * font / options.height : 0.03;
    if (options.forces) window.y0 = 0.17;  // above the arrow legends (scene_extras.h)
    window.y1 = content_top;
    std::vector<Eigen::Vector3d> view_hull, ground_hull;
    for (const CameraBox& box : frame_boxes) {
      for (const Eigen::Vector3d& p : box.corners()) view_hull.push_back(p);
    }
    for (const CameraBox& box : ground_boxes) {
      for (const Eigen::Vector3d& p : box.corners()) ground_hull.push_back(axes.of(p));
    }
    const double aspect = static_cast<double>(options.width) / options.height;
    const CameraPlacement by_view = fit_camera(view_hull, axes, kViewAngleDeg, aspect, window);
    const CameraPlacement by_ground = fit_camera(ground_hull, axes, kViewAngleDeg, aspect, window);
    const CameraPlacement& placement = by_view.eye_back <= by_ground.eye_back ? by_view : by_ground;
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

namespace {

// Display coordinates (pixels, x right, y up) to columns and rows from the top, widened by
// `margin` pixels and clipped to the frame.
PixelBox pixel_box(int width, int height, double x_min, double x_max, double y_min, double y_max,
                   int margin) {
  PixelBox b;
  b.x0 = std::max(0, static_cast<int>(std::floor(x_min)) - margin);
  b.x1 = std::min(width, static_cast<int>(std::ceil(x_max)) + 1 + margin);
  b.y0 = std::max(0, height - 1 - static_cast<int>(std::ceil(y_max)) - margin);
  b.y1 = std::min(height, height - static_cast<int>(std::floor(y_min)) + margin);
  return b;
}

// A text's pixels: its bounding box about the anchor (justification included) moved to the
// anchor's pixel, widened by `margin`; nothing for an empty text.
std::optional<PixelBox> text_box(vtkTextActor* text, vtkRenderer* renderer, int width, int height,
                                 int margin) {
  double b[4];  // x min, x max, y min, y max
  text->GetBoundingBox(renderer, b);
  const int* anchor = text->GetPositionCoordinate()->GetComputedDisplayValue(renderer);
  if (b[1] < b[0] || b[3] < b[2]) return std::nullopt;  // nothing drawn
  return pixel_box(width, height, anchor[0] + b[0], anchor[0] + b[1], anchor[1] + b[2],
                   anchor[1] + b[3], margin);
}

}  // namespace

std::vector<PixelBox> Scene::overlay_boxes() const {
  const Impl& s = *impl_;
  const int width = s.options.width;
  const int height = s.options.height;
  std::vector<PixelBox> boxes;

  // Texts, plus 2 pixels (FXAA reads the neighbours).
  for (const auto& text : s.texts) {
    if (const auto b = text_box(text, s.renderer, width, height, 2)) boxes.push_back(*b);
  }

  // Colour bar: its box, plus one label height, which its title and labels may overrun.
  if (s.bar) {
    const double x = kColorBarBox[0] * width;
    const double y = kColorBarBox[1] * height;
    boxes.push_back(pixel_box(width, height, x, x + kColorBarBox[2] * width, y,
                              y + kColorBarBox[3] * height, s.bar_font));
  }
  return boxes;
}

std::vector<Scene::DrawnText> Scene::drawn_texts() const {
  const Impl& s = *impl_;
  std::vector<DrawnText> drawn;
  for (const auto& text : s.texts) {
    const auto b = text_box(text, s.renderer, s.options.width, s.options.height, 0);
    if (!b) continue;
    const std::string input = text->GetInput() != nullptr ? text->GetInput() : "";
    drawn.push_back({input, 1 + static_cast<int>(std::count(input.begin(), input.end(), '\n')), *b});
  }
  return drawn;
}

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
    for (Eigen::Index k = 0; k < x_W.rows(); ++k) {
      view.points->SetPoint(k, x_W(k, 0), x_W(k, 1), x_W(k, 2));
      view.magnitude->SetValue(k, s.per_unit * u_norm(k));
    }
    view.points->Modified();
    view.magnitude->Modified();
    // Beam solids: each point at its node, offset by the undeformed section turned with the body.
    if (view.solids) {
      const Eigen::Matrix3d R = state.orientation.toRotationMatrix();
      const RowMatrix3d offset_W = view.solid_offset_B * R.transpose();
      vtkPoints* points = view.solids->GetPoints();
      for (Eigen::Index k = 0; k < offset_W.rows(); ++k) {
        const int node = view.solid_mesh.node[static_cast<std::size_t>(k)];
        points->SetPoint(k, x_W(node, 0) + offset_W(k, 0), x_W(node, 1) + offset_W(k, 1),
                         x_W(node, 2) + offset_W(k, 2));
        view.solid_magnitude->SetValue(k, s.per_unit * u_norm(node));
      }
      points->Modified();
      view.solid_magnitude->Modified();
    }
    // Element stresses of the history row at or before t [MPa] (lines first, then quads).
    if (view.stress) {
      const int lines = static_cast<int>(view.body->mesh.lines.rows());
      const Eigen::VectorXd values =
          view.stress->element_values(view.stress->row_at(t), lines + static_cast<int>(view.body->mesh.quads.rows())) / 1e6;
      if (view.line_stress) {
        for (int e = 0; e < lines; ++e) view.line_stress->SetValue(e, values(e));
        view.line_stress->Modified();
      }
      if (view.solid_stress) {
        for (int c = 0; c < view.solid_mesh.cell_count(); ++c) {
          view.solid_stress->SetValue(c, values(view.solid_mesh.beam[static_cast<std::size_t>(c)]));
        }
        view.solid_stress->Modified();
      }
      if (view.quad_stress) {
        for (Eigen::Index q = 0; q < view.body->mesh.quads.rows(); ++q) view.quad_stress->SetValue(q, values(lines + q));
        view.quad_stress->Modified();
      }
    }
    if (view.surface) view.surface->Modified();
    if (view.beams) view.beams->Modified();
    if (view.solids) view.solids->Modified();
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
  }
  s.extras->update(at);

  // Time stamp and, for a follow camera, the centroid of the body frames.
  char stamp[96];
  const double slow = slow_motion(s.options);
  if (std::abs(slow - 1.0) < 1e-9) {
    std::snprintf(stamp, sizeof stamp, "t = %.4f s", t);
  } else {
    std::snprintf(stamp, sizeof stamp, "t = %.4f s  (%.3gx slow motion)", t, slow);
  }
  s.time_text->SetInput(stamp);
  s.event_text->SetInput(event_stamp(s.results.events, t, s.event_hold).c_str());
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
