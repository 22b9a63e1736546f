// Section properties (beam_section.h) against closed forms and published tables.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "fe/beam_section.h"
#include "fe_test_support.h"

namespace limber::fe {
namespace {

using testing::input_error_of;
using testing::relative_error;

TEST(BeamSection, RectangleAreaAndSecondMoments) {
  // Exact formulas; round-off only.
  const BeamSection s = rectangle_section(0.01, 0.02);
  EXPECT_LT(relative_error(s.area, 2e-4), 1e-14);
  EXPECT_LT(relative_error(s.inertia_y, 0.01 * std::pow(0.02, 3) / 12.0), 1e-14);
  EXPECT_LT(relative_error(s.inertia_z, 0.02 * std::pow(0.01, 3) / 12.0), 1e-14);
  EXPECT_DOUBLE_EQ(s.shear_factor_y, 5.0 / 6.0);
  EXPECT_DOUBLE_EQ(s.shear_factor_z, 5.0 / 6.0);
}

TEST(BeamSection, SquareTorsionConstantIsTabulatedValue) {
  // J = 0.1406 a^4 (Roark's Formulas for Stress and Strain, torsion of a solid rectangle;
  // Timoshenko & Goodier give k1 = 0.141): the 4-digit value bounds the error by 5e-5 a^4.
  const double a = 0.03;
  EXPECT_NEAR(rectangle_torsion_constant(a, a) / std::pow(a, 4), 0.1406, 5e-5);
}

TEST(BeamSection, RectangleTorsionConstantMatchesTimoshenkoGoodierTable) {
  // J = k1 a b^3 with k1 tabulated to 3 digits for a/b = 1.5 ... 10 (Timoshenko & Goodier,
  // Theory of Elasticity, 3rd ed., table of torsion of rectangular bars): |error| <= 5e-4.
  const double b = 0.01;
  const std::array<std::pair<double, double>, 7> table{{{1.5, 0.196},
                                                        {2.0, 0.229},
                                                        {2.5, 0.249},
                                                        {3.0, 0.263},
                                                        {4.0, 0.281},
                                                        {5.0, 0.291},
                                                        {10.0, 0.312}}};
  for (const auto& [ratio, k1] : table) {
    const double a = ratio * b;
    EXPECT_NEAR(rectangle_torsion_constant(a, b) / (a * b * b * b), k1, 5e-4) << "a/b " << ratio;
    // Order of the sides does not matter.
    EXPECT_DOUBLE_EQ(rectangle_torsion_constant(b, a), rectangle_torsion_constant(a, b));
  }
}

TEST(BeamSection, ThinRectangleApproachesOpenSectionLimit) {
  // Thin strip: J -> a b^3 (1/3 - 0.2101 b/a) (the series with tanh = 1:
  // (64/pi^5) (31/32) zeta(5) = 0.210083); at a/b = 100 tanh(50 pi) = 1 to machine precision,
  // so only round-off remains (1e-12). The crude a b^3 / 3 is 0.063 % high at a/b = 100.
  const double a = 1.0;
  const double b = 0.01;
  const double zeta5 = 1.0369277551433699;
  const double coefficient = 64.0 / std::pow(std::numbers::pi, 5) * (31.0 / 32.0) * zeta5;
  const double j = rectangle_torsion_constant(a, b);
  EXPECT_LT(relative_error(j, a * b * b * b * (1.0 / 3.0 - coefficient * b / a)), 1e-12);
  EXPECT_NEAR(coefficient, 0.210083, 1e-6);
  EXPECT_GT(relative_error(j, a * b * b * b / 3.0), 6e-3);
}

TEST(BeamSection, CircleIsExact) {
  // A = pi d^2/4, I = pi d^4/64, J = pi d^4/32 (exact for a circle); Cowper's k at nu = 0.3
  // is 7.8 / 8.8.
  const double d = 0.05;
  const double pi = std::numbers::pi;
  const BeamSection s = circle_section(d);
  EXPECT_LT(relative_error(s.area, pi * d * d / 4.0), 1e-14);
  EXPECT_LT(relative_error(s.inertia_y, pi * std::pow(d, 4) / 64.0), 1e-14);
  EXPECT_DOUBLE_EQ(s.inertia_y, s.inertia_z);
  EXPECT_LT(relative_error(s.torsion_constant, pi * std::pow(d, 4) / 32.0), 1e-14);
  EXPECT_LT(relative_error(s.shear_factor_y, 7.8 / 8.8), 1e-14);
  EXPECT_LT(relative_error(circle_section(d, 0.0).shear_factor_z, 6.0 / 7.0), 1e-14);
}

TEST(BeamSection, NonPositiveSizesThrow) {
  EXPECT_EQ(input_error_of([] { rectangle_section(0.0, 0.02); }),
            "rectangle section width (local y): expected a positive finite size [m], got 0");
  EXPECT_EQ(input_error_of([] { rectangle_section(0.01, -0.02); }),
            "rectangle section height (local z): expected a positive finite size [m], got -0.02");
  EXPECT_EQ(input_error_of([] { circle_section(-1.0); }),
            "circle section diameter: expected a positive finite size [m], got -1");
  EXPECT_EQ(input_error_of([] { circle_section(0.1, 0.5); }),
            "circle section Poisson ratio: expected -1 < nu < 0.5, got 0.5");
}

}  // namespace
}  // namespace limber::fe
