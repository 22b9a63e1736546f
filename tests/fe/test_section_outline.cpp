// Section outlines (section_outline.h) against the sections' closed forms: the shoelace area
// and second moments of the rectangle, box and tube outlines equal A, Iy, Iz of
// beam_section.h / the textbook formulas; the circle's 16-gon against the inscribed regular
// polygon's exact formulas and, within its stated shortfall, against the circle.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "fe/beam_section.h"
#include "fe/section_outline.h"

namespace limber::fe {
namespace {

// Sums of a few dozen products of centimetre-sized numbers: round-off ~1e-15 relative; a
// wrong corner changes A or I by percents.
constexpr double kRoundOff = 1e-12;

void expect_matches(const SectionOutline& outline, double area, double iy, double iz) {
  const PolygonProperties p = polygon_properties(outline);
  EXPECT_NEAR(p.area, area, kRoundOff * area);
  EXPECT_NEAR(p.inertia_y, iy, kRoundOff * iy);
  EXPECT_NEAR(p.inertia_z, iz, kRoundOff * iz);
  // About the centroid, principal axes along y and z.
  const double size = std::sqrt(area);
  EXPECT_NEAR(p.first_moment.norm(), 0.0, kRoundOff * area * size);
  EXPECT_NEAR(p.product, 0.0, kRoundOff * (iy + iz));
}

TEST(SectionOutline, RectangleOutlineHasTheRectanglesSecondMoments) {
  const BeamSection s = rectangle_section(0.04, 0.005);
  ASSERT_EQ(s.outline.points.size(), 4u);
  EXPECT_FALSE(s.outline.hollow || s.outline.equivalent);
  expect_matches(s.outline, 0.04 * 0.005, 0.04 * std::pow(0.005, 3) / 12.0,
                 0.005 * std::pow(0.04, 3) / 12.0);
}

TEST(SectionOutline, BoxOutlineIsOuterMinusInnerRectangle) {
  // 60 (y) x 40 (z) mm, walls 3 mm across y and 2 mm across z.
  const double wy = 0.06, hz = 0.04, ty = 0.003, tz = 0.002;
  const SectionOutline o = box_outline(wy, hz, ty, tz);
  EXPECT_TRUE(o.hollow);
  const double wi = wy - 2 * ty, hi = hz - 2 * tz;
  expect_matches(o, wy * hz - wi * hi, (wy * std::pow(hz, 3) - wi * std::pow(hi, 3)) / 12.0,
                 (hz * std::pow(wy, 3) - hi * std::pow(wi, 3)) / 12.0);
}

// Inscribed regular n-gon of circumradius R: A = n/2 R² sin(2π/n), I about any centroidal axis
// = n R⁴/24 sin(2π/n) (2 + cos(2π/n)) (exact; e.g. Roark, "regular polygon" section).
double polygon_area(int n, double r) { return 0.5 * n * r * r * std::sin(2 * std::numbers::pi / n); }
double polygon_inertia(int n, double r) {
  const double a = 2 * std::numbers::pi / n;
  return n * std::pow(r, 4) / 24.0 * std::sin(a) * (2.0 + std::cos(a));
}

TEST(SectionOutline, TubeOutlineIsTheDifferenceOfTwoInscribed16Gons) {
  const double ro = 0.02, ri = 0.015;
  const SectionOutline o = tube_outline(2 * ro, 2 * ri);
  ASSERT_EQ(o.points.size(), 2u * kCircleOutlineSides);
  const int n = kCircleOutlineSides;
  const double i = polygon_inertia(n, ro) - polygon_inertia(n, ri);
  expect_matches(o, polygon_area(n, ro) - polygon_area(n, ri), i, i);
}

TEST(SectionOutline, CircleSixteenGonFallsShortOfTheCircleByItsStatedFraction) {
  const double d = 0.03, r = d / 2;
  const BeamSection s = circle_section(d);
  const int n = kCircleOutlineSides;
  // Exact against the inscribed 16-gon.
  expect_matches(s.outline, polygon_area(n, r), polygon_inertia(n, r), polygon_inertia(n, r));
  // Against the circle: the 16-gon has 2.55 % less area and 5.02 % less I (from the formulas
  // above: 8 sin(π/8)/π = 0.9745, 2/3 sin(π/8)(2 + cos(π/8))/(π/4) = 0.9498); 3 % and 6 % bound it.
  const PolygonProperties p = polygon_properties(s.outline);
  EXPECT_NEAR(p.area / s.area, 1.0, 0.03);
  EXPECT_LT(p.area, s.area);
  EXPECT_NEAR(p.inertia_y / s.inertia_y, 1.0, 0.06);
  EXPECT_NEAR(p.inertia_z / s.inertia_z, 1.0, 0.06);
}

TEST(SectionOutline, CentredPolygonMovesToTheCentroidAndTurnsCounterClockwise) {
  // A clockwise 2 x 1 rectangle with its corner at (3, 5): centroid (4, 5.5).
  const SectionOutline o = centred_polygon({{3, 5}, {3, 6}, {5, 6}, {5, 5}});
  expect_matches(o, 2.0, 2.0 / 12.0, 8.0 / 12.0);
  // Reversed: (5, 5) first, moved by (-4, -5.5); the centroid carries round-off.
  EXPECT_NEAR(o.points[0].x(), 1.0, 1e-12);
  EXPECT_NEAR(o.points[0].y(), -0.5, 1e-12);
}

TEST(SectionOutline, EquivalentOutlineUsesTheFibresElseASquareOfTheArea) {
  const SectionOutline fibres = equivalent_outline(1e-4, 0.01, 0.002);
  EXPECT_TRUE(fibres.equivalent);
  EXPECT_NEAR(polygon_properties(fibres).area, 0.02 * 0.004, kRoundOff * 8e-5);
  const SectionOutline square = equivalent_outline(1e-4, 0.0, 0.0);
  EXPECT_TRUE(square.equivalent);
  expect_matches(square, 1e-4, 1e-8 / 12.0, 1e-8 / 12.0);
}

}  // namespace
}  // namespace limber::fe
