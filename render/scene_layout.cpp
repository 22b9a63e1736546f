#include "scene_layout.h"

#include "scene.h"
#include "scene_labels.h"
#include "world_triad.h"

#include <vtkCamera.h>
#include <vtkRenderer.h>

#include <algorithm>
#include <cmath>
#include <optional>

namespace limber::render {
namespace {

// Gaps about an overlay (viewport units): the triad's also covers the perspective, which draws
// it a little larger or smaller away from where its footprint was measured.
constexpr double kLegendGap = 0.005;
constexpr double kTriadGap = 0.015;
// The triad's arrows: a round length near this fraction of the frame's height at the content's
// mid depth (0.07 to 0.175 of it: a length scale that reads, in a corner it can find free).
constexpr double kTriadFraction = 0.1;

// Three point sets whose hulls each hold the whole motion (camera axes): the corners of each
// frame's box in camera axes, in ground axes, and of the boxes about each part.
struct MotionHulls {
  std::vector<Eigen::Vector3d> view, ground, parts;
  MotionHulls(const MotionExtent& motion, const CameraAxes& axes) {
    for (const CameraBox& box : motion.view_boxes) {
      for (const Eigen::Vector3d& p : box.corners()) view.push_back(p);
    }
    for (const CameraBox& box : motion.ground_boxes) {
      for (const Eigen::Vector3d& p : box.corners()) ground.push_back(axes.of(p));
    }
    for (const PartCorners& part : motion.parts_C) parts.insert(parts.end(), part.begin(), part.end());
  }
};

// The camera nearest to the motion over the three hulls (any of them shows it all).
CameraPlacement nearest_fit(const MotionHulls& hulls, const CameraAxes& axes, double aspect, const ViewWindow& window) {
  std::optional<CameraPlacement> best;
  for (const std::vector<Eigen::Vector3d>* hull : {&hulls.view, &hulls.ground, &hulls.parts}) {
    if (hull->empty()) continue;
    const CameraPlacement other = fit_camera(*hull, axes, kViewAngleDeg, aspect, window);
    if (!best || other.eye_back < best->eye_back) best = other;
  }
  return *best;
}

// The frame less its fixed texts (normalised viewport): what the motion and the floating
// overlays share.
ViewWindow free_area(const RenderOptions& options, const SceneLabels& labels) {
  ViewWindow area;
  area.x0 = 0.02;
  area.x1 = labels.has_color_bar() ? kColorBarBox[0] - 0.02 : 0.98;
  area.y0 = options.time_stamp ? 0.03 + 1.6 * labels.stamp_font() / options.height : 0.03;
  if (options.forces) area.y0 = 0.17;  // above the arrow legends (scene_extras.h)
  area.y1 = labels.title_bottom();
  return area;
}

// Where the overlays go with one camera; nothing for an overlay without a free corner.
struct OverlayPlaces {
  std::optional<ViewRect> legend, triad;
};

// The triad's footprint with its origin at the area's centre at the content's mid depth, and
// the origin's offset from the footprint's lower left corner (viewport units).
struct TriadFootprint {
  ViewRect rect;
  Eigen::Vector2d origin_offset;
};

class Layout {
 public:
  Layout(const MotionExtent& motion, const CameraAxes& axes, const RenderOptions& options, SceneLabels& labels,
         WorldTriad* triad, vtkCamera* camera)
      : camera_(camera), motion_(motion), hulls_(motion, axes), axes_(axes), options_(options), labels_(labels),
        triad_(triad),
        aspect_(static_cast<double>(options.width) / options.height), area_(free_area(options, labels)) {}

  // Fits, places the overlays, and gives a strip to any that found no free corner; after the
  // third fit an overlay still without one goes to its strip's corner (the legend top right,
  // the triad bottom left), which the motion, fitted without the strip, leaves free.
  void run() {
    ViewWindow window = area_;
    has_legend_ = labels_.legend_size().x() > 0.0;
    const Eigen::Vector2d legend = labels_.legend_size() + 2.0 * kLegendGap * Eigen::Vector2d::Ones();
    for (int attempt = 0;; ++attempt) {
      const CameraPlacement placement = nearest_fit(hulls_, axes_, aspect_, window);
      const TriadFootprint triad = triad_footprint(placement);
      OverlayPlaces places = find_places(placement, legend, triad);
      const bool legend_missing = has_legend_ && !places.legend;
      const bool triad_missing = triad_ && !places.triad;
      if ((!legend_missing && !triad_missing) || attempt == 2) {
        if (legend_missing) places.legend = rect_in_corner(area_, Corner::kTopRight, legend.x(), legend.y());
        if (triad_missing) places.triad = rect_in_corner(area_, Corner::kBottomLeft, width(triad), height(triad));
        apply(placement, places, triad);
        return;
      }
      if (legend_missing) window.y1 = std::min(window.y1, area_.y1 - legend.y());
      if (triad_missing) window.y0 = std::max(window.y0, area_.y0 + height(triad));
    }
  }

 private:
  static double width(const TriadFootprint& f) { return f.rect.x1 - f.rect.x0 + 2.0 * kTriadGap; }
  static double height(const TriadFootprint& f) { return f.rect.y1 - f.rect.y0 + 2.0 * kTriadGap; }

  double focal_back(const CameraPlacement& placement) const { return axes_.back.dot(placement.focal); }
  Eigen::Vector3d ground_of(const Eigen::Vector3d& p_C) const {
    return p_C.x() * axes_.right + p_C.y() * axes_.up + p_C.z() * axes_.back;
  }

  // Sizes the triad for `placement` and measures its footprint.
  TriadFootprint triad_footprint(const CameraPlacement& placement) {
    if (!triad_) return {};
    const double frame_height = 2.0 * (placement.eye_back - focal_back(placement)) *
                                std::tan(0.5 * kViewAngleDeg * M_PI / 180.0);  // [m] at the focal depth
    triad_->set_length(round_length(kTriadFraction * frame_height));
    const Eigen::Vector2d centre(0.5 * (area_.x0 + area_.x1), 0.5 * (area_.y0 + area_.y1));
    const Eigen::Vector3d origin_W =
        ground_of(point_at_viewport(placement, centre, focal_back(placement), kViewAngleDeg, aspect_));
    const auto to_viewport = [&](const Eigen::Vector3d& p_W) {
      return viewport_point(placement, axes_.of(p_W), kViewAngleDeg, aspect_);
    };
    const ViewRect rect = triad_->footprint(origin_W, to_viewport, options_.width, options_.height);
    return {rect, centre - Eigen::Vector2d(rect.x0, rect.y0)};
  }

  OverlayPlaces find_places(const CameraPlacement& placement, const Eigen::Vector2d& legend,
                            const TriadFootprint& triad) const {
    const ProjectedMotion projected(motion_.parts_C, placement, kViewAngleDeg, aspect_);
    OverlayPlaces places;
    std::vector<ViewRect> taken;
    if (has_legend_) {
      places.legend = free_corner(projected, area_,
                                  {Corner::kTopRight, Corner::kTopLeft, Corner::kBottomRight, Corner::kBottomLeft},
                                  legend.x(), legend.y(), {});
      if (places.legend) taken.push_back(*places.legend);
    }
    if (triad_) {
      places.triad = free_corner(projected, area_,
                                 {Corner::kBottomLeft, Corner::kTopLeft, Corner::kBottomRight, Corner::kTopRight},
                                 width(triad), height(triad), taken);
    }
    return places;
  }

  // Sets the camera, the legend (right-aligned in a right corner) and the triad's origin.
  void apply(const CameraPlacement& placement, const OverlayPlaces& places, const TriadFootprint& triad) {
    if (places.legend) {
      const ViewRect& r = *places.legend;
      const ViewRect text{r.x0 + kLegendGap, r.x1 - kLegendGap, r.y0 + kLegendGap, r.y1 - kLegendGap};
      labels_.place_legend(text, r.x1 >= area_.x1 - 1e-12);
    }
    if (places.triad) {
      const Eigen::Vector2d at = Eigen::Vector2d(places.triad->x0 + kTriadGap, places.triad->y0 + kTriadGap) +
                                 triad.origin_offset;
      triad_->place(ground_of(point_at_viewport(placement, at, focal_back(placement), kViewAngleDeg, aspect_)));
    }
    vtkCamera* camera = camera_;
    camera->SetViewAngle(kViewAngleDeg);
    camera->SetPosition(placement.eye.data());
    camera->SetFocalPoint(placement.focal.data());
    camera->SetViewUp(axes_.up.data());
    camera->SetWindowCenter(-placement.axis_at.x(), -placement.axis_at.y());
  }

  vtkCamera* camera_;
  const MotionExtent& motion_;
  MotionHulls hulls_;
  CameraAxes axes_;
  const RenderOptions& options_;
  SceneLabels& labels_;
  WorldTriad* triad_;
  double aspect_;
  ViewWindow area_;
  bool has_legend_ = false;
};

}  // namespace

void fit_camera_and_overlays(vtkRenderer* renderer, const MotionExtent& motion, const CameraAxes& axes,
                             const RenderOptions& options, SceneLabels& labels, WorldTriad* triad) {
  Layout(motion, axes, options, labels, triad, renderer->GetActiveCamera()).run();
}

}  // namespace limber::render
