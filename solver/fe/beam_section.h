// Section properties of common solid beam cross-sections, in the beam's local y-z plane
// (see fe_model.h: Iy is about local y, i.e. bending in the local x-z plane).
// Units: lengths [m], areas [m^2], second moments and torsion constants [m^4].
#pragma once

#include "fe/fe_model.h"

namespace limber::fe {

// Solid rectangle, `width_y` along local y and `height_z` along local z:
//   A = w h,  Iy = w h^3 / 12,  Iz = h w^3 / 12,
//   J = St-Venant torsion constant (rectangle_torsion_constant),
//   shear factors k = 5/6 in both directions (Timoshenko 1921 / Cowper 1966, rectangle),
//   extreme fibres at w/2 (local y) and h/2 (local z).
// Outline: the rectangle (section_outline.h).
// Throws InputError when a size is not > 0 (or not finite).
BeamSection rectangle_section(double width_y, double height_z);

// Solid circle of diameter d: A = pi d^2 / 4, Iy = Iz = pi d^4 / 64, J = pi d^4 / 32
// (exact for a circle). Shear factor from Cowper 1966 (J. Appl. Mech. 33:335):
//   k = 6 (1 + nu) / (7 + 6 nu)   (= 6/7 at nu = 0, 0.886 at nu = 0.3);
// extreme fibre at d/2, marked circular (bending stress from the resultant moment).
// Outline: the inscribed 16-gon (section_outline.h).
// Throws InputError when d is not > 0 or nu is outside (-1, 0.5).
BeamSection circle_section(double diameter, double poisson_ratio = 0.3);

// St-Venant torsion constant of a solid a x b rectangle (any order of the sides), by the
// series of Timoshenko & Goodier, "Theory of Elasticity" (1951), §109, with a >= b:
//   J = a b^3 [1/3 - (64 / pi^5) (b/a) sum_{n = 1,3,5,...} tanh(n pi a / (2 b)) / n^5].
// Summed until the terms fall below double precision. Square: J = 0.1406 a^4.
// Throws InputError when a side is not > 0.
double rectangle_torsion_constant(double side_1, double side_2);

}  // namespace limber::fe
