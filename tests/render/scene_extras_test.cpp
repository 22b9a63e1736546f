// Orientation aids of `limber render` (render/scene_extras.h, render/mode_view.h), on frames
// rendered offscreen from runs of the built `limber run`:
//  - the pin glyph's colour at the projected revolute joint (front view: the pin axis, ground y,
//    points at the camera, so its end cap covers the joint point);
//  - the slide arrow beyond the slider along the slide axis, the rail behind it over the travel;
//  - the reaction-force arrow of a crank at constant speed along the closed-form direction (the
//    pin pulls the crank towards the axis: from the pin away from the crank), none the other way;
//  - the reaction-torque arrow of an arm held by a bracket under gravity: T = -m g L y, its
//    double-headed arrow's direction and length in pixels from the projection, drawn over the
//    arm it starts inside;
//  - the ghost outline where the undeformed beam lies and the deformed one does not;
//  - the force scale's bounds, and the mode plane of a beam's in- and out-of-plane modes.
#include "frame_renderer.h"
#include "mode_animation.h"
#include "mode_view.h"
#include "scene.h"
#include "scene_extras.h"
#include "world_triad.h"

#include "test_dir.h"
#include "test_results.h"

#include <gtest/gtest.h>

#include <vtkActor.h>
#include <vtkActorCollection.h>
#include <vtkRenderer.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <limits>

namespace limber::render {
namespace {

constexpr int kWidth = 480, kHeight = 360;

// Runs `limber run` on `case_text` into a fresh directory and reads the results.
Results run_case(const std::string& name, const std::string& case_text) {
  const auto dir = testing::fresh_directory("extras_" + name);
  std::filesystem::create_directories(dir);
  const auto case_file = dir / "case.yaml";
  std::ofstream(case_file) << case_text;
  const std::string command = std::string(LIMBER_EXE) + " run " + case_file.string() + " -o " +
                              (dir / "run").string() + " > " + (dir / "log").string() + " 2>&1";
  EXPECT_EQ(std::system(command.c_str()), 0);
  return read_results(dir / "run");
}

// A rigid crank (0.3 kg, centre of mass 0.025 m from the pin) at 5 rev/s about ground y, no
// gravity; its shapes around the pin: a grey cylinder along y and a box along the crank.
const char* kCrank = R"(title: crank
gravity: [0, 0, 0]
bodies:
  crank:
    mass: 0.3
    inertia: [2.8125e-5, 6.8125e-5, 8.5e-5]
    center_of_mass: [0.025, 0, 0]
    position: [0, 0, 0]
    shapes:
      - {type: box, size: [0.05, 0.03, 0.015], position: [0.025, 0, 0], color: [0.85, 0.35, 0.2]}
      - {type: cylinder, radius: 0.01, length: 0.04, orientation: {z_axis: [0, 1, 0]}, color: [0.3, 0.3, 0.3]}
joints:
  R1: {type: revolute, body_i: ground, body_j: crank, position: [0, 0, 0],
       orientation: {z_axis: [0, 1, 0], x_axis: [1, 0, 0]}}
drivers:
  D1: {joint: R1, motion: {type: constant_speed, initial: 0, speed: 31.41592653589793}}
run: {integrator: ida, rtol: 1.0e-8, atol: 1.0e-10, t_end: 0.1, sample_interval: 0.01}
)";

// A 0.1 m block sliding on a ground rail along x at 1 m/s for 0.2 s.
const char* kSlider = R"(title: slider
gravity: [0, 0, 0]
bodies:
  block:
    mass: 1.0
    inertia: [4.1667e-4, 4.1667e-4, 4.1667e-4]
    position: [0, 0, 0]
    shapes:
      - {type: box, size: [0.1, 0.05, 0.05], color: [0.25, 0.5, 0.3]}
joints:
  T: {type: translational, body_i: ground, body_j: block, position: [0, 0, 0],
      orientation: {z_axis: [1, 0, 0], x_axis: [0, 1, 0]}}
drivers:
  D1: {joint: T, motion: {type: constant_speed, initial: 0, speed: 1.0}}
run: {integrator: ida, t_end: 0.2, sample_interval: 0.01}
)";

// A 2 kg arm, centre of mass L = 0.1 m along x from a bracket (fixed joint) at the ground
// origin, under gravity 9.81 m/s^2 along -z; its box spans the joint point (x from -0.02 to
// 0.22 m, y and z within +-0.03 m).
constexpr double kArmMass = 2.0, kArmLever = 0.1, kGravity = 9.81;
const char* kArm = R"(title: arm
gravity: [0, 0, -9.81]
bodies:
  arm:
    mass: 2.0
    inertia: [1.2e-3, 1.0e-2, 1.0e-2]
    center_of_mass: [0.1, 0, 0]
    position: [0, 0, 0]
    shapes:
      - {type: box, size: [0.24, 0.06, 0.06], position: [0.1, 0, 0], color: [0.25, 0.5, 0.3]}
joints:
  B: {type: bracket, body_i: ground, body_j: arm, position: [0, 0, 0]}
run: {integrator: ida, t_end: 0.1, sample_interval: 0.05}
)";

RenderOptions front_view() {
  RenderOptions options;
  options.width = kWidth;
  options.height = kHeight;
  options.camera = CameraPreset::kFront;
  options.ground = false;
  options.world_triad = false;
  options.time_stamp = false;
  options.anti_aliasing = AntiAliasing::kNone;
  return options;
}

// Whether a pixel has the hue of `color`: each channel within `tolerance` of c × s for one
// shading factor s in [0.3, 1.3] (the glyphs are lit mostly ambient: s varies with the light,
// the ratio of the channels does not; the bound keeps the light grey background, s > 1.8 for
// every grey here, from passing for a dark grey).
bool has_hue(const std::array<int, 3>& pixel, const std::array<double, 3>& color, int tolerance = 25) {
  const double brightest = std::max({color[0], color[1], color[2]});
  const double s = std::max({pixel[0], pixel[1], pixel[2]}) / (255.0 * brightest);
  for (int c = 0; c < 3; ++c) {
    if (std::abs(pixel[c] - 255.0 * s * color[c]) > tolerance) return false;
  }
  return s > 0.3 && s < 1.3;
}

// Pixels with the hue along the segment between two projected points (inclusive), counted.
int count_along(const Image& image, const Eigen::Vector2d& from, const Eigen::Vector2d& to,
                const std::array<double, 3>& color) {
  const int steps = static_cast<int>(std::ceil((to - from).norm())) + 1;
  int found = 0;
  for (int k = 0; k <= steps; ++k) {
    const Eigen::Vector2d p = from + (to - from) * (static_cast<double>(k) / steps);
    const int x = static_cast<int>(std::lround(p.x())), y = static_cast<int>(std::lround(p.y()));
    if (x < 0 || y < 0 || x >= image.width || y >= image.height) continue;
    found += has_hue(image.pixel(x, y), color) ? 1 : 0;
  }
  return found;
}

TEST(SceneExtras, PinGlyphAtTheProjectedRevoluteAndForceArrowAlongTheCentripetalPull) {
  unsetenv("DISPLAY");
  const Results results = run_case("crank", kCrank);
  ASSERT_TRUE(results.joints.at(0).has_markers());
  RenderOptions options = front_view();
  options.forces = true;
  FrameRenderer renderer(results, options, 0.0, 0.1);
  const Image image = renderer.render(0.0);
  // The joint point (ground origin) shows the pin's amber, not the crank's grey cylinder.
  const Eigen::Vector2d pin = renderer.project(Eigen::Vector3d::Zero());
  const auto p = image.pixel(static_cast<int>(pin.x()), static_cast<int>(pin.y()));
  EXPECT_TRUE(has_hue(p, kPinAxisColor)) << p[0] << " " << p[1] << " " << p[2];
  // At t = 0 the crank lies along +x; the force on it, m r w^2 = 7.4 N, points from the pin to
  // -x. Its arrow shows along -x beyond the pin cap (radius < 0.01 m), none along +x.
  const int minus_x = count_along(image, renderer.project({-0.012, 0.0, 0.0}), renderer.project({-0.2, 0.0, 0.0}),
                                  kForceColor);
  const int plus_x = count_along(image, renderer.project({0.012, 0.0, 0.0}), renderer.project({0.2, 0.0, 0.0}),
                                 kForceColor);
  EXPECT_GT(minus_x, 3);
  EXPECT_EQ(plus_x, 0);
  // The planar crank's reaction torques about x and z are round-off at most (the driver carries
  // the one about the pin): no torque arrow, no torque scale.
  EXPECT_EQ(renderer.scene().extras().newton_metres_per_metre(), 0.0);
  int torque_pixels = 0;
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) torque_pixels += has_hue(image.pixel(x, y), kTorqueColor) ? 1 : 0;
  }
  EXPECT_EQ(torque_pixels, 0);
}

// The test scene's joint "pin" as a hold-down released at 0.5 s (results.h5
// /joints/pin@release_time, test_results.h): read back, its joint sphere is drawn up to the
// release (the frame at that instant included: it still carries its load there) and not
// after; nothing else in the scene appears or goes.
TEST(SceneExtras, ReleasedHoldDownIsNotDrawnAfterItsRelease) {
  unsetenv("DISPLAY");
  const auto dir = testing::fresh_directory("released_pin");
  testing::TestScene test_scene;
  test_scene.with_beam = false;
  test_scene.pin_release_time = 0.5;
  testing::write_test_results(dir, test_scene);
  const Results results = read_results(dir);
  ASSERT_EQ(results.joints.size(), 1u);
  EXPECT_EQ(results.joints[0].release_time, 0.5);
  Scene scene(results, front_view(), 0.0, 1.0);
  const auto visible_actors = [&](double t) {
    scene.update(t);
    int visible = 0;
    vtkActorCollection* actors = scene.renderer()->GetActors();
    actors->InitTraversal();
    while (vtkActor* actor = actors->GetNextActor()) visible += actor->GetVisibility() != 0 ? 1 : 0;
    return visible;
  };
  const int held = visible_actors(0.2);
  EXPECT_EQ(visible_actors(0.5), held);
  EXPECT_EQ(visible_actors(0.6), held - 1);
  EXPECT_EQ(visible_actors(1.0), held - 1);
  // A file without the attribute: the joint held throughout, drawn at every time.
  const auto kept = testing::fresh_directory("kept_pin");
  test_scene.pin_release_time = -1.0;
  testing::write_test_results(kept, test_scene);
  EXPECT_EQ(read_results(kept).joints[0].release_time, std::numeric_limits<double>::infinity());
}

TEST(SceneExtras, SlideArrowBeyondTheSliderAndTheRailOverItsTravel) {
  unsetenv("DISPLAY");
  const Results results = run_case("slider", kSlider);
  ASSERT_TRUE(results.joints.at(0).has_markers());
  // Travel (p_j − p_i)·z_i from 0 to 0.2 m (1 m/s for 0.2 s), to IDA's tolerance.
  const std::array<double, 2> travel = slide_travel(results.joints[0]);
  EXPECT_NEAR(travel[0], 0.0, 1e-9);
  EXPECT_NEAR(travel[1], 0.2, 1e-6);
  FrameRenderer renderer(results, front_view(), 0.0, 0.2);
  const Image image = renderer.render(0.0);
  // The block spans x in [-0.05, 0.05] at t = 0: the arrow from the joint along +x shows past
  // it (its length is at least twice the block's radius 0.061 m), then the rail on the axis up
  // to the travel's end 0.2 m plus its margin (max(0.25 x 0.2 m, 0.15 x the scene radius)).
  EXPECT_GT(count_along(image, renderer.project({0.06, 0, 0}), renderer.project({0.09, 0, 0}), kSlideAxisColor), 2);
  EXPECT_GT(count_along(image, renderer.project({0.15, 0, 0}), renderer.project({0.24, 0, 0}), kRailColor), 20);
  EXPECT_EQ(count_along(image, renderer.project({0.15, 0, 0.02}), renderer.project({0.24, 0, 0.02}), kRailColor), 0);
  EXPECT_EQ(count_along(image, renderer.project({0.45, 0, 0}), renderer.project({0.6, 0, 0}), kRailColor), 0);
}

TEST(SceneExtras, GhostOutlineWhereTheUndeformedBeamLies) {
  unsetenv("DISPLAY");
  // A straight 1 m beam along x bending in z: phi_z = sin(pi x); at a quarter period the
  // midspan has moved 0.1 m up, and the undeformed line y = z = 0 shows the ghost's grey there.
  BodyModeShapes beam;
  beam.name = "beam";
  const int nodes = 21;
  beam.mesh.nodes.setZero(nodes, 3);
  beam.mesh.lines.resize(nodes - 1, 2);
  beam.mesh.mode_translations.setZero(3 * nodes, 1);
  for (int n = 0; n < nodes; ++n) {
    beam.mesh.nodes(n, 0) = n / (nodes - 1.0);
    beam.mesh.mode_translations(3 * n + 2, 0) = std::sin(M_PI * n / (nodes - 1.0));
    if (n + 1 < nodes) beam.mesh.lines.row(n) << n, n + 1;
  }
  beam.mesh.frequencies_hz = Eigen::VectorXd::Constant(1, 10.0);
  beam.kinds = {"normal"};
  beam.labels = {"normal 1"};
  ModeAnimationOptions animation;
  const Results results = mode_results(beam, 0, animation);
  const double lift = results.bodies[0].modal_coordinates(6, 0);  // A sin(pi/2) at the midspan
  EXPECT_GT(lift, 0.05);
  RenderOptions options = front_view();
  for (bool ghost : {true, false}) {
    // One renderer (one EGL context) at a time.
    options.ghost = ghost;
    FrameRenderer renderer(results, options, 0.0, 0.1);
    const Image image = renderer.render(0.025);  // T / 4: eta = A
    const int grey = count_along(image, renderer.project({0.4, 0, 0}), renderer.project({0.6, 0, 0}), kGhostColor);
    // Without --ghost nothing grey lies there.
    if (ghost) EXPECT_GT(grey, 10);
    else EXPECT_EQ(grey, 0);
  }
}

TEST(SceneExtras, TorqueArrowOfABracketedArmUnderGravityOverTheArm) {
  unsetenv("DISPLAY");
  const Results results = run_case("arm", kArm);
  ASSERT_EQ(results.joints.size(), 1u);
  const JointTrack& joint = results.joints[0];
  ASSERT_EQ(joint.torque_ground.rows(), results.sample_count());
  // Statics: the bracket carries the weight, F = m g z, and its moment about the joint,
  // T = -(L x) x (-m g z) = -m g L y (1.962 N m). The arm does not move: IDA's residual at
  // rtol 1e-6 leaves ~1e-6 relative.
  const Eigen::Vector3d T_expected(0.0, -kArmMass * kGravity * kArmLever, 0.0);
  EXPECT_LT((joint.torque_ground.row(0).transpose() - T_expected).norm(), 1e-5 * T_expected.norm());
  EXPECT_NEAR(joint.force_ground(0, 2), kArmMass * kGravity, 1e-5 * kArmMass * kGravity);

  RenderOptions options = front_view();
  options.camera = CameraPreset::kTop;  // the torque, along -y, in the picture's plane
  options.width = 2 * kWidth;            // the arrow some 60 px long: 2 px is 3 %
  options.height = 2 * kHeight;
  options.forces = true;
  FrameRenderer renderer(results, options, 0.0, 0.1);
  const Image image = renderer.render(0.0);
  // The arrow is |T| / (N m per m) long along -y from the joint; the scale is round: the peak
  // 1.962 N m is drawn with 1 N m per round length.
  const double per_metre = renderer.scene().extras().newton_metres_per_metre();
  ASSERT_GT(per_metre, 0.0);
  const double length = T_expected.norm() / per_metre;
  const Eigen::Vector2d joint_px = renderer.project(Eigen::Vector3d::Zero());
  const Eigen::Vector2d tip_px = renderer.project(length * -Eigen::Vector3d::UnitY());
  const double length_px = (tip_px - joint_px).norm();
  ASSERT_GT(length_px, 40.0);
  // Along -y: the shaft and both heads up to the tip; the last pixel of the arrow's colour on
  // the line within 2 px of the projected tip (the cone's apex is rasterised to about a pixel);
  // nothing along +y nor beyond the tip.
  const Eigen::Vector2d along = (tip_px - joint_px) / length_px;
  int last = -1;
  for (int k = 0; k <= static_cast<int>(length_px) + 10; ++k) {
    const Eigen::Vector2d p = joint_px + k * along;
    if (has_hue(image.pixel(static_cast<int>(std::lround(p.x())), static_cast<int>(std::lround(p.y()))),
                kTorqueColor)) {
      last = k;
    }
  }
  EXPECT_NEAR(last, length_px, 2.0);
  EXPECT_EQ(count_along(image, renderer.project({0.0, 0.01, 0.0}), renderer.project({0.0, length, 0.0}),
                        kTorqueColor),
            0);
  // Over the arm: where the shaft runs inside the box (y from -0.01 to -0.028 m, under its top
  // face at z = 0.03 m) the arrow's colour shows.
  const int inside = count_along(image, renderer.project({0.0, -0.01, 0.0}), renderer.project({0.0, -0.028, 0.0}),
                                 kTorqueColor);
  const double inside_px = (renderer.project({0.0, -0.01, 0.0}) - renderer.project({0.0, -0.028, 0.0})).norm();
  EXPECT_GT(inside, 0.8 * inside_px);
  // Two heads, each 0.25 of the length: just past each head's base (0.53 and 0.78 of the length,
  // cone radius 0.88 of the tip radius 0.1) the arrow is wider than across its shaft (radius
  // 0.03) by more than 3 px (about 5 px at this size; one head would leave 0.53 at the shaft's
  // width).
  const auto width_at = [&](double s) {
    const Eigen::Vector3d c = s * length * -Eigen::Vector3d::UnitY();
    const double half = 0.1 * length;
    return count_along(image, renderer.project(c - half * Eigen::Vector3d::UnitX()),
                       renderer.project(c + half * Eigen::Vector3d::UnitX()), kTorqueColor);
  };
  const int shaft = width_at(0.3);
  EXPECT_GT(shaft, 0);
  EXPECT_GT(width_at(0.53), shaft + 3);
  EXPECT_GT(width_at(0.78), shaft + 3);
}

TEST(SceneExtras, ArrowScaleIsRoundAndThePeakArrowAFewTenthsOfTheScene) {
  // round_length returns 0.7 to 1.75 times its argument, so the peak's arrow, peak / (V/L),
  // is 0.1 to 0.625 of the scene radius: never a speck, never across the picture.
  for (double peak : {7.4, 829.0, 2210.0, 0.013, 5e6}) {
    for (double radius : {0.05, 0.6, 3.0, 40.0}) {
      const ArrowScale scale = arrow_scale(peak, radius);
      EXPECT_EQ(scale.value, round_length(scale.value));
      EXPECT_EQ(scale.length, round_length(scale.length));
      const double arrow = peak / scale.per_metre();
      EXPECT_GE(arrow, 0.1 * radius) << peak << " " << radius;
      EXPECT_LE(arrow, 0.625 * radius) << peak << " " << radius;
    }
  }
  // The slider-crank's figure: a peak of 2210 N in a 0.6 m scene is drawn at 0.1 m = 1000 N.
  EXPECT_DOUBLE_EQ(arrow_scale(2210.0, 0.6).value, 1000.0);
  EXPECT_DOUBLE_EQ(arrow_scale(2210.0, 0.6).length, 0.1);
}

TEST(ModeView, BeamModesAreSeenSquareToTheirPlane) {
  FlexibleMesh beam;
  beam.nodes.setZero(11, 3);
  for (int n = 0; n < 11; ++n) beam.nodes(n, 0) = 0.1 * n;
  beam.mode_translations.setZero(33, 3);
  for (int n = 0; n < 11; ++n) {
    const double shape = std::sin(M_PI * n / 10.0);
    beam.mode_translations(3 * n + 1, 0) = shape;        // bending in y
    beam.mode_translations(3 * n + 2, 1) = shape;        // bending in z
    beam.mode_translations(3 * n + 0, 2) = 0.1 * n;      // axial
  }
  const std::optional<ModeView> in_y = mode_view(beam, 0);
  ASSERT_TRUE(in_y.has_value());
  EXPECT_EQ(in_y->plane, "body x-y plane");
  EXPECT_NEAR(std::abs(in_y->direction.z()), 1.0, 1e-12);
  // Looking along z (up = y): x runs to the right, so the eye is on +z (right = -z × y = x).
  EXPECT_GT(in_y->direction.z(), 0.0);
  const std::optional<ModeView> in_z = mode_view(beam, 1);
  ASSERT_TRUE(in_z.has_value());
  EXPECT_EQ(in_z->plane, "body x-z plane");
  EXPECT_LT(in_z->direction.y(), -1.0 + 1e-12);  // as the front preset: eye on -y
  // Axial: the view is square to x (the motion), whichever normal.
  const std::optional<ModeView> axial = mode_view(beam, 2);
  ASSERT_TRUE(axial.has_value());
  EXPECT_NEAR(axial->direction.x(), 0.0, 1e-12);
  // A plate is not slender: the preset view stays.
  FlexibleMesh plate;
  plate.nodes.resize(11 * 7, 3);
  for (int i = 0; i < 11; ++i) {
    for (int j = 0; j < 7; ++j) plate.nodes.row(7 * i + j) << 0.1 * i, 0.1 * j, 0.0;
  }
  plate.mode_translations = Eigen::MatrixXd::Ones(3 * 77, 1);
  EXPECT_FALSE(mode_view(plate, 0).has_value());
}

}  // namespace
}  // namespace limber::render
