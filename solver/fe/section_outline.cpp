#include "fe/section_outline.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/error.h"

namespace limber::fe {

namespace {

// Signed area, first moments and second moments of one closed polygon (header formulas).
PolygonProperties loop_properties(const Eigen::Vector2d* p, std::size_t n) {
  PolygonProperties out;
  for (std::size_t i = 0; i < n; ++i) {
    const Eigen::Vector2d& a = p[i];
    const Eigen::Vector2d& b = p[(i + 1) % n];
    const double c = a.x() * b.y() - b.x() * a.y();
    out.area += 0.5 * c;
    out.first_moment += c / 6.0 * (a + b);
    out.inertia_z += c / 12.0 * (a.x() * a.x() + a.x() * b.x() + b.x() * b.x());
    out.inertia_y += c / 12.0 * (a.y() * a.y() + a.y() * b.y() + b.y() * b.y());
    out.product += c / 24.0 * (a.x() * b.y() + 2.0 * a.x() * a.y() + 2.0 * b.x() * b.y() + b.x() * a.y());
  }
  return out;
}

// `sides` corners on the circle of radius r, counter-clockwise from +y.
std::vector<Eigen::Vector2d> regular_polygon(double r, int sides) {
  std::vector<Eigen::Vector2d> points;
  for (int k = 0; k < sides; ++k) {
    const double angle = 2.0 * std::numbers::pi * k / sides;
    points.emplace_back(r * std::cos(angle), r * std::sin(angle));
  }
  return points;
}

// Corners of the centred rectangle wy x hz, counter-clockwise.
std::vector<Eigen::Vector2d> rectangle_corners(double wy, double hz) {
  return {{-0.5 * wy, -0.5 * hz}, {0.5 * wy, -0.5 * hz}, {0.5 * wy, 0.5 * hz}, {-0.5 * wy, 0.5 * hz}};
}

}  // namespace

PolygonProperties polygon_properties(const SectionOutline& outline) {
  const std::size_t n = outline.hollow ? outline.points.size() / 2 : outline.points.size();
  PolygonProperties total = loop_properties(outline.points.data(), n);
  if (outline.hollow) {
    // The inner polygon is counter-clockwise too: subtract it.
    const PolygonProperties hole = loop_properties(outline.points.data() + n, n);
    total.area -= hole.area;
    total.first_moment -= hole.first_moment;
    total.inertia_y -= hole.inertia_y;
    total.inertia_z -= hole.inertia_z;
    total.product -= hole.product;
  }
  return total;
}

SectionOutline rectangle_outline(double width_y, double height_z) {
  return {rectangle_corners(width_y, height_z), false, false};
}

SectionOutline circle_outline(double diameter, int sides) {
  LIMBER_DEMAND(sides >= 3);
  return {regular_polygon(0.5 * diameter, sides), false, false};
}

SectionOutline tube_outline(double outer_diameter, double inner_diameter, int sides) {
  LIMBER_DEMAND(sides >= 3 && inner_diameter < outer_diameter);
  SectionOutline outline{regular_polygon(0.5 * outer_diameter, sides), true, false};
  const std::vector<Eigen::Vector2d> inner = regular_polygon(0.5 * inner_diameter, sides);
  outline.points.insert(outline.points.end(), inner.begin(), inner.end());
  return outline;
}

SectionOutline box_outline(double width_y, double height_z, double wall_y, double wall_z) {
  LIMBER_DEMAND(2.0 * wall_y < width_y && 2.0 * wall_z < height_z);
  SectionOutline outline{rectangle_corners(width_y, height_z), true, false};
  const std::vector<Eigen::Vector2d> inner =
      rectangle_corners(width_y - 2.0 * wall_y, height_z - 2.0 * wall_z);
  outline.points.insert(outline.points.end(), inner.begin(), inner.end());
  return outline;
}

SectionOutline centred_polygon(std::vector<Eigen::Vector2d> points) {
  const PolygonProperties p = loop_properties(points.data(), points.size());
  LIMBER_DEMAND(p.area != 0.0);
  // Centroid to the origin; clockwise input reversed.
  const Eigen::Vector2d centroid = p.first_moment / p.area;
  for (Eigen::Vector2d& point : points) point -= centroid;
  if (p.area < 0.0) std::reverse(points.begin(), points.end());
  return {std::move(points), false, false};
}

SectionOutline equivalent_outline(double area, double fibre_y, double fibre_z) {
  LIMBER_DEMAND(area > 0.0);
  SectionOutline outline = fibre_y > 0.0 && fibre_z > 0.0
                               ? rectangle_outline(2.0 * fibre_y, 2.0 * fibre_z)
                               : rectangle_outline(std::sqrt(area), std::sqrt(area));
  outline.equivalent = true;
  return outline;
}

}  // namespace limber::fe
