// The outline of a beam cross-section in the beam's local y-z plane, for drawing beams as swept
// solids (render/beam_solids.h). Not used by the mechanics: A, I and J stay in BeamSection.
//
// Points are (y, z) [m] about the centroid (the beam axis). A solid section is one closed
// polygon counter-clockwise about local x (positive area ½ Σ (y_i z_{i+1} − y_{i+1} z_i));
// a hollow one (tube, box) is an outer polygon followed by an inner one with as many points,
// both counter-clockwise, inner point i across from outer point i. The polygon's area and
// second moments (polygon_properties) are those of the section exactly, except a circle's
// inscribed 16-gon (2.5 % less area, 5 % less I) and equivalent outlines (A, I only given).
#pragma once

#include <Eigen/Core>
#include <vector>

namespace limber::fe {

struct SectionOutline {
  std::vector<Eigen::Vector2d> points;  // (y, z) [m]: the outer polygon, then the inner one
  bool hollow = false;                  // true: the second half of `points` is the inner polygon
  bool equivalent = false;              // true: a stand-in drawn from A and I (or the fibres)

  bool empty() const { return points.empty(); }
};

// Area and second moments of an outline about the origin, exact for polygons (the shoelace
// formulas; Steger 1996, "On the calculation of arbitrary moments of polygons"):
//   A   = ½ Σ c_i,                          c_i = y_i z_{i+1} − y_{i+1} z_i
//   S_y = ⅙ Σ c_i (y_i + y_{i+1}),          S_z likewise (first moments)
//   Izz = ∫ y² dA = 1/12 Σ c_i (y_i² + y_i y_{i+1} + y_{i+1}²)   (BeamSection::inertia_z)
//   Iyy = ∫ z² dA = 1/12 Σ c_i (z_i² + z_i z_{i+1} + z_{i+1}²)   (BeamSection::inertia_y)
//   Iyz = ∫ y z dA = 1/24 Σ c_i (y_i z_{i+1} + 2 y_i z_i + 2 y_{i+1} z_{i+1} + y_{i+1} z_i)
// A hollow outline's inner polygon is subtracted. Units m², m³, m⁴.
struct PolygonProperties {
  double area = 0.0;
  Eigen::Vector2d first_moment = Eigen::Vector2d::Zero();  // (∫ y dA, ∫ z dA)
  double inertia_y = 0.0;                                 // ∫ z² dA
  double inertia_z = 0.0;                                 // ∫ y² dA
  double product = 0.0;                                   // ∫ y z dA
};
PolygonProperties polygon_properties(const SectionOutline& outline);

// Outline builders; sizes [m] > 0 as the matching section constructors check them.
// Solid rectangle, `width_y` along y, `height_z` along z, centred.
SectionOutline rectangle_outline(double width_y, double height_z);
// Inscribed regular polygon of `sides` corners on the circle of `diameter` (a corner on +y).
inline constexpr int kCircleOutlineSides = 16;
SectionOutline circle_outline(double diameter, int sides = kCircleOutlineSides);
// Tube: two inscribed polygons, outer and inner diameters.
SectionOutline tube_outline(double outer_diameter, double inner_diameter,
                            int sides = kCircleOutlineSides);
// Hollow rectangle: outer `width_y` x `height_z`, walls `wall_y` thick across y (the walls
// normal to y) and `wall_z` across z.
SectionOutline box_outline(double width_y, double height_z, double wall_y, double wall_z);
// A closed polygon given in any orientation and about any origin: moved to its centroid and
// made counter-clockwise. Precondition (LIMBER_DEMAND): non-zero area.
SectionOutline centred_polygon(std::vector<Eigen::Vector2d> points);
// The stand-in for a section known only by A and second moments: the rectangle of its extreme
// fibres 2 fibre_y x 2 fibre_z when both are known (> 0), else the square of area `area`;
// marked equivalent.
SectionOutline equivalent_outline(double area, double fibre_y, double fibre_z);

}  // namespace limber::fe
