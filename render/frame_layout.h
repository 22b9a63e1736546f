// Where the overlays that float over an animation's frame go (issue 28: the deployed array fills
// the frame). The fixed camera is fitted to the motion alone (camera_fit.h); the deformation
// legend and the world triad then take a corner of the frame that no body reaches at any time,
// checked against the projection of a box about every body, primitive, joint and glyph at every
// sample. Only when no corner is free does an overlay get a strip of its own, which the camera
// is fitted again without (render/scene.cpp). Pure geometry: no VTK.
#pragma once

#include "camera_fit.h"

#include <Eigen/Core>

#include <array>
#include <optional>
#include <vector>

namespace limber::render {

// The DPI at which VTK draws texts in limber's windows (vtkWindow's default, which they keep):
// overlays measure their texts with it before the first frame.
inline constexpr int kTextDpi = 72;

// A rectangle in normalised viewport coordinates (0..1, x right, y up).
struct ViewRect {
  double x0 = 0.0, x1 = 0.0, y0 = 0.0, y1 = 0.0;
  bool intersects(const ViewRect& other) const {
    return x0 < other.x1 && other.x0 < x1 && y0 < other.y1 && other.y0 < y1;
  }
};

enum class Corner { kTopLeft, kTopRight, kBottomLeft, kBottomRight };

// The rectangle `width` x `height` (viewport units) in `corner` of `area`.
ViewRect rect_in_corner(const ViewWindow& area, Corner corner, double width, double height);

// The corners of a box about one part of one frame (a body's deformed mesh or a primitive in
// its own axes, a glyph's box; a joint point repeated), camera coordinates [m].
using PartCorners = std::array<Eigen::Vector3d, 8>;

// The whole motion as one camera draws it: per part and sample, the convex outline of its
// box's projection. Any picture of the part lies inside that outline.
class ProjectedMotion {
 public:
  // Precondition: every point in front of the eye.
  ProjectedMotion(const std::vector<PartCorners>& parts_C, const CameraPlacement& placement,
                  double view_angle_deg, double aspect);
  // Whether some part's outline meets `rect`.
  bool overlaps(const ViewRect& rect) const;

 private:
  struct Outline {
    ViewRect box;                       // the outline's bounding box, a quick rejection
    std::vector<Eigen::Vector2d> hull;  // counter-clockwise convex hull
  };
  std::vector<Outline> outlines_;
};

// The first of `candidates` (corners of `area`) where a `width` x `height` rectangle meets no
// part of the motion and none of `taken`; nothing when every candidate is occupied.
std::optional<ViewRect> free_corner(const ProjectedMotion& motion, const ViewWindow& area,
                                    const std::vector<Corner>& candidates, double width, double height,
                                    const std::vector<ViewRect>& taken);

}  // namespace limber::render
