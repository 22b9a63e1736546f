#include "frame_layout.h"

#include <algorithm>

namespace limber::render {
namespace {

double cross(const Eigen::Vector2d& o, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return (a.x() - o.x()) * (b.y() - o.y()) - (a.y() - o.y()) * (b.x() - o.x());
}

// Andrew's monotone chain: the convex hull, counter-clockwise, without repeated points (one
// point, or two for a segment, when the input is degenerate).
std::vector<Eigen::Vector2d> convex_hull(std::vector<Eigen::Vector2d> points) {
  std::sort(points.begin(), points.end(), [](const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
  });
  points.erase(std::unique(points.begin(), points.end()), points.end());
  if (points.size() < 3) return points;
  std::vector<Eigen::Vector2d> hull(2 * points.size());
  std::size_t k = 0;
  // Lower chain left to right, then upper chain right to left.
  for (std::size_t i = 0; i < points.size(); ++i) {
    while (k >= 2 && cross(hull[k - 2], hull[k - 1], points[i]) <= 0.0) --k;
    hull[k++] = points[i];
  }
  for (std::size_t i = points.size() - 1, lower = k + 1; i-- > 0;) {
    while (k >= lower && cross(hull[k - 2], hull[k - 1], points[i]) <= 0.0) --k;
    hull[k++] = points[i];
  }
  hull.resize(k - 1);
  return hull;
}

// Separating axes (Gottschalk, Lin & Manocha 1996, "OBBTree"): a convex polygon and an
// axis-aligned rectangle whose bounding boxes meet are apart exactly when one polygon edge has
// the whole rectangle on its outer side.
bool hull_meets_rect(const std::vector<Eigen::Vector2d>& hull, const ViewRect& r) {
  const std::array<Eigen::Vector2d, 4> corners{Eigen::Vector2d(r.x0, r.y0), Eigen::Vector2d(r.x1, r.y0),
                                               Eigen::Vector2d(r.x1, r.y1), Eigen::Vector2d(r.x0, r.y1)};
  if (hull.size() < 2) return true;  // a point: inside the rectangle since the boxes meet
  for (std::size_t i = 0; i < hull.size(); ++i) {
    const Eigen::Vector2d& a = hull[i];
    const Eigen::Vector2d& b = hull[(i + 1) % hull.size()];
    // Counter-clockwise: the outer side of a -> b is on its right, cross < 0.
    const bool all_outside = std::all_of(corners.begin(), corners.end(),
                                         [&](const Eigen::Vector2d& c) { return cross(a, b, c) <= 0.0; });
    if (all_outside) return false;
  }
  return true;
}

}  // namespace

ViewRect rect_in_corner(const ViewWindow& area, Corner corner, double width, double height) {
  const bool left = corner == Corner::kTopLeft || corner == Corner::kBottomLeft;
  const bool top = corner == Corner::kTopLeft || corner == Corner::kTopRight;
  ViewRect r;
  r.x0 = left ? area.x0 : area.x1 - width;
  r.x1 = r.x0 + width;
  r.y0 = top ? area.y1 - height : area.y0;
  r.y1 = r.y0 + height;
  return r;
}

ProjectedMotion::ProjectedMotion(const std::vector<PartCorners>& parts_C, const CameraPlacement& placement,
                                 double view_angle_deg, double aspect) {
  outlines_.reserve(parts_C.size());
  std::vector<Eigen::Vector2d> projected(8);
  for (const PartCorners& part : parts_C) {
    Outline outline;
    outline.box = {1e300, -1e300, 1e300, -1e300};
    for (std::size_t k = 0; k < part.size(); ++k) {
      projected[k] = viewport_point(placement, part[k], view_angle_deg, aspect);
      outline.box.x0 = std::min(outline.box.x0, projected[k].x());
      outline.box.x1 = std::max(outline.box.x1, projected[k].x());
      outline.box.y0 = std::min(outline.box.y0, projected[k].y());
      outline.box.y1 = std::max(outline.box.y1, projected[k].y());
    }
    outline.hull = convex_hull(projected);
    outlines_.push_back(std::move(outline));
  }
}

bool ProjectedMotion::overlaps(const ViewRect& rect) const {
  return std::any_of(outlines_.begin(), outlines_.end(), [&](const Outline& o) {
    // Closed boxes: a point part on the rectangle's edge counts as meeting it.
    const bool boxes_meet = o.box.x0 <= rect.x1 && rect.x0 <= o.box.x1 && o.box.y0 <= rect.y1 && rect.y0 <= o.box.y1;
    return boxes_meet && hull_meets_rect(o.hull, rect);
  });
}

std::optional<ViewRect> free_corner(const ProjectedMotion& motion, const ViewWindow& area,
                                    const std::vector<Corner>& candidates, double width, double height,
                                    const std::vector<ViewRect>& taken) {
  for (Corner corner : candidates) {
    const ViewRect rect = rect_in_corner(area, corner, width, height);
    const bool clear = std::none_of(taken.begin(), taken.end(), [&](const ViewRect& t) { return t.intersects(rect); });
    if (clear && !motion.overlaps(rect)) return rect;
  }
  return std::nullopt;
}

}  // namespace limber::render
