// Orientation aids drawn over the scene of `limber render` (issue 15, docs/rendering.md
// "Joint glyphs, rails, ghost, force arrows"), kept apart from scene.cpp:
//  - joint axis glyphs, from the joint markers' orientations in results.h5: a revolute or
//    cylindrical joint gets a short cylinder along its pin axis (marker j's z), a translational
//    one an arrow along its slide axis (marker i's z) from the joint point; each 0.12 (pin) or
//    0.22 (arrow) of the scene radius long, or 1.5 times as far as the shapes of the joint's
//    bodies that hold the joint point reach along the axis, if more, so it sticks out of them;
//    the translational joint's rail is a line along that axis over
//    the travel of the run (min..max of (p_j − p_i)·z_i, longer each side by 1/4 of the
//    travel or 0.15 of the scene radius, whichever is more), carried by
//    body i;
//  - with options.ghost: each flexible body's undeformed outline (its mesh edges at the rigid
//    fit through its joint nodes, relative_deflection.h, i.e. without the scaled deflection);
//  - with options.forces: the reaction force and torque on body j at every joint
//    (force_ground, torque_ground about the joint point): the force a single-headed arrow from
//    the joint point, |F| / (newtons per metre) long; the torque a double-headed arrow along its
//    vector (right-hand rule, the moment symbol of Adams and RecurDyn), |T| / (newton metres
//    per metre) long; each with its own scale, a round number chosen so the largest value in
//    the time range is about a quarter of the scene, stated in a legend ("force arrows: 0.1 m =
//    50 N (reaction on body j)", "torque arrows (double head): 0.1 m = 2 N m (...)"); torques
//    whose peak is below 1e-6 of (largest force x scene radius) are round-off, not drawn, and
//    the legend says "torques ~ 0 (peak ...)". The
//    arrows are drawn in an overlay layer (overlay()) that shares the camera and is drawn after
//    the bodies with its own depth buffer, so a body never hides an arrow that starts inside it.
// Internal to limber_render (exposes VTK types).
#pragma once

#include "body_pose.h"
#include "relative_deflection.h"
#include "render_options.h"
#include "results_reader.h"

#include <vtkSmartPointer.h>

#include <array>
#include <memory>
#include <vector>

class vtkRenderer;
class vtkTextActor;

namespace limber::render {

// Colours (RGB 0..1); tests look for them in frames.
inline constexpr std::array<double, 3> kPinAxisColor{0.95, 0.70, 0.10};    // revolute pin
inline constexpr std::array<double, 3> kSlideAxisColor{0.10, 0.55, 0.95};  // translational arrow
inline constexpr std::array<double, 3> kRailColor{0.20, 0.20, 0.22};
inline constexpr std::array<double, 3> kGhostColor{0.45, 0.45, 0.50};
inline constexpr std::array<double, 3> kForceColor{0.80, 0.10, 0.60};
inline constexpr std::array<double, 3> kTorqueColor{0.05, 0.60, 0.45};

class SceneExtras {
 public:
  // `scene_radius` [m]: the radius of everything drawn over the time range, which sizes the
  // glyphs; [t0, t1] the time range (the force scale's peak is taken over it).
  SceneExtras(const Results& results, const RenderOptions& options, vtkRenderer* renderer,
              double scene_radius, double t0, double t1);
  ~SceneExtras();
  SceneExtras(const SceneExtras&) = delete;
  SceneExtras& operator=(const SceneExtras&) = delete;

  // Moves every glyph, rail, outline and arrow to the time `at`.
  void update(const SampleBracket& at);
  // Corners of the joint glyphs' and rails' boxes (ground) as last updated: what the fixed
  // camera must also hold (a slider's rail reaches past the bodies).
  std::vector<Eigen::Vector3d> glyph_corners() const;
  // The legend texts added (for the overlay boxes FXAA leaves alone).
  std::vector<vtkSmartPointer<vtkTextActor>> texts() const;
  // Newtons per metre of force arrow and newton metres per metre of torque arrow (0 without
  // arrows).
  double newtons_per_metre() const;
  double newton_metres_per_metre() const;
  // The renderer of the arrows, to draw in layer 1 of the window after the scene's renderer
  // (layer 0), with its camera; null without options.forces.
  vtkRenderer* overlay() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// A renderer drawn over `scene` in layer 1 with its camera: it clears only the depth buffer, so
// what it draws shows whole over the scene's bodies and hides itself correctly.
vtkSmartPointer<vtkRenderer> overlay_layer(vtkRenderer* scene);

// Marker pose between samples: origin interpolated linearly, orientation by slerp.
// Precondition: the marker track has the results' ns rows.
void marker_pose(const MarkerTrack& marker, const SampleBracket& at, Eigen::Vector3d& p_W,
                 Eigen::Matrix3d& R_WM);

// The scale of force or torque arrows for the largest value `peak` [N or N m] in a scene of
// radius `scene_radius` [m]: a round value (1, 2 or 5 × 10^k near peak / 2) drawn as a round
// length (near 1/8 of the scene radius), so the peak's arrow is about a quarter of the radius.
struct ArrowScale {
  double value = 0.0;   // [N or N m]
  double length = 0.0;  // [m]
  double per_metre() const { return value / length; }
};
ArrowScale arrow_scale(double peak, double scene_radius);

// Travel of a translational joint along marker i's z over the whole run: min and max of
// (p_j − p_i)·z_i [m].
std::array<double, 2> slide_travel(const JointTrack& joint);

}  // namespace limber::render
