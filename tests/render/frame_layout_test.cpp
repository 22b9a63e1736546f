// Where the frame's floating overlays go (frame_layout.h): a rectangle meets the projection of a
// part exactly when the part's convex outline reaches into it, not merely its bounding box, and
// the first free corner is taken; the projection helpers of camera_fit.h invert each other.
#include "frame_layout.h"

#include <gtest/gtest.h>

#include <cmath>

namespace limber::render {
namespace {

constexpr double kAngle = 90.0;  // vertical view angle [deg]: tan(45 deg) = 1
constexpr double kAspect = 1.0;

// A diamond |r| + |u| <= 1 facing the camera at depth 0, fitted into the whole frame: the eye
// at back = 1 sees it as the diamond |x - 0.5| + |y - 0.5| <= 0.5 (viewport units), touching
// the frame's four sides.
struct Diamond {
  CameraAxes axes = camera_axes(Eigen::Vector3d::UnitZ(), Eigen::Vector3d::UnitY());
  std::vector<PartCorners> parts;
  CameraPlacement placement;
  Diamond() {
    const std::array<Eigen::Vector3d, 4> tips{Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(0, 1, 0),
                                              Eigen::Vector3d(-1, 0, 0), Eigen::Vector3d(0, -1, 0)};
    PartCorners& part = parts.emplace_back();
    for (std::size_t k = 0; k < part.size(); ++k) part[k] = tips[k % 4];
    const std::vector<Eigen::Vector3d> points(part.begin(), part.end());
    placement = fit_camera(points, axes, kAngle, kAspect, ViewWindow{});
  }
};

TEST(FrameLayout, TheDiamondFillsTheFrame) {
  const Diamond d;
  EXPECT_NEAR(d.placement.eye_back, 1.0, 1e-8);  // the bisection's tolerance, 1e-9 of the extent
  const Eigen::Vector2d right = viewport_point(d.placement, Eigen::Vector3d(1, 0, 0), kAngle, kAspect);
  const Eigen::Vector2d top = viewport_point(d.placement, Eigen::Vector3d(0, 1, 0), kAngle, kAspect);
  EXPECT_NEAR(right.x(), 1.0, 1e-8);
  EXPECT_NEAR(right.y(), 0.5, 1e-8);
  EXPECT_NEAR(top.x(), 0.5, 1e-8);
  EXPECT_NEAR(top.y(), 1.0, 1e-8);
}

TEST(FrameLayout, PointAtViewportInvertsTheProjection) {
  // Any placement and depth: the point found projects back where asked, to round-off.
  const Diamond d;
  for (const double back : {0.5, -3.0}) {
    for (const Eigen::Vector2d& v : {Eigen::Vector2d(0.1, 0.9), Eigen::Vector2d(0.7, 0.2)}) {
      const Eigen::Vector3d p = point_at_viewport(d.placement, v, back, kAngle, kAspect);
      EXPECT_DOUBLE_EQ(p.z(), back);
      EXPECT_LT((viewport_point(d.placement, p, kAngle, kAspect) - v).norm(), 1e-12);
    }
  }
}

TEST(FrameLayout, ARectangleMeetsThePartsOutlineNotItsBoundingBox) {
  // The frame's corners lie in the diamond's bounding box but outside the diamond: a 0.2 square
  // in a corner reaches (0.2, 0.2), at |x - 0.5| + |y - 0.5| = 0.6 > 0.5 from the centre, free;
  // a 0.3 square reaches 0.4 < 0.5, inside.
  const Diamond d;
  const ProjectedMotion motion(d.parts, d.placement, kAngle, kAspect);
  const ViewWindow frame;
  EXPECT_FALSE(motion.overlaps(rect_in_corner(frame, Corner::kBottomLeft, 0.2, 0.2)));
  EXPECT_FALSE(motion.overlaps(rect_in_corner(frame, Corner::kTopRight, 0.2, 0.2)));
  EXPECT_TRUE(motion.overlaps(rect_in_corner(frame, Corner::kBottomLeft, 0.3, 0.3)));
  EXPECT_TRUE(motion.overlaps(ViewRect{0.45, 0.55, 0.45, 0.55}));  // wholly inside
}

TEST(FrameLayout, TheFirstFreeCornerNotTakenIsChosen) {
  const Diamond d;
  const ProjectedMotion motion(d.parts, d.placement, kAngle, kAspect);
  const ViewWindow frame;
  const std::vector<Corner> order{Corner::kBottomLeft, Corner::kTopLeft, Corner::kTopRight};
  const std::optional<ViewRect> first = free_corner(motion, frame, order, 0.2, 0.2, {});
  ASSERT_TRUE(first);
  EXPECT_DOUBLE_EQ(first->x0, 0.0);
  EXPECT_DOUBLE_EQ(first->y0, 0.0);
  // Bottom left taken: top left, x in [0, 0.2], y in [0.8, 1].
  const std::optional<ViewRect> second = free_corner(motion, frame, order, 0.2, 0.2, {*first});
  ASSERT_TRUE(second);
  EXPECT_DOUBLE_EQ(second->x0, 0.0);
  EXPECT_DOUBLE_EQ(second->y1, 1.0);
  // Too large for any corner.
  EXPECT_FALSE(free_corner(motion, frame, order, 0.3, 0.3, {}));
}

}  // namespace
}  // namespace limber::render
