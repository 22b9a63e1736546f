// The fixed camera of an animation and the overlays that float over its frame (issue 28: the
// deployed array fills the frame, no text cut off). The camera is fitted to the motion alone
// (camera_fit.h), into the frame less its fixed texts: under the title, above the time and
// event stamps (and the arrow legends), left of the colour bar. The deformation legend then
// takes the first of the top right, top left, bottom right and bottom left corners, and the
// world triad (also the length scale, at the content's mid depth) the first of the bottom left,
// top left, bottom right and top right corners, that the motion's projection leaves free at
// every sample (frame_layout.h). An overlay that finds no free corner gets a strip of its own
// (the legend's at the top, the triad's at the bottom) and the camera is fitted again without
// it. Internal to limber_render (exposes VTK types).
#pragma once

#include "camera_fit.h"
#include "frame_layout.h"
#include "render_options.h"

#include <Eigen/Core>

#include <vector>

class vtkRenderer;

namespace limber::render {

class SceneLabels;
class WorldTriad;

// The camera's vertical view angle [deg].
inline constexpr double kViewAngleDeg = 30.0;

// What the camera and the layout need of the whole motion in [t0, t1].
struct MotionExtent {
  std::vector<CameraBox> view_boxes;    // per sample: everything drawn, camera axes [m]
  std::vector<CameraBox> ground_boxes;  // per sample: everything drawn, ground axes [m]
  // Per sample, a box about each part in its own axes (a body's deformed mesh, a primitive, a
  // joint glyph or rail; a joint point), camera axes: tight where a part lies askew (a deployed
  // wing seen from iso).
  std::vector<PartCorners> parts_C;
};

// Sets `renderer`'s camera along `axes` (looking along -back) to hold the whole motion and
// places the legend of `labels` and `triad` (null: none), as above.
void fit_camera_and_overlays(vtkRenderer* renderer, const MotionExtent& motion, const CameraAxes& axes,
                             const RenderOptions& options, SceneLabels& labels, WorldTriad* triad);

}  // namespace limber::render
