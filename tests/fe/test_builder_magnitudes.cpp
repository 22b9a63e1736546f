// FeModelBuilder's range of element, point-mass and DOF-matrix magnitudes (issue 31): material
// and section values at extreme magnitudes are InputErrors at the element, naming the first
// diagonal entry outside 1e-300 to 1e300 and its closed-form value.
#include <gtest/gtest.h>

#include "fe/fe_model_builder.h"
#include "fe_test_support.h"

namespace limber::fe {
namespace {

using testing::input_error_of;
using testing::paper_rod_property;

const SourceLocation kWhere{"case.yaml", 12, 5};
const Eigen::Vector3d kZ = Eigen::Vector3d::UnitZ();

// A 1 m beam along x (nodes 1, 2) of the paper's rod (A = 2e-4 m^2) with E and rho given.
std::string beam_error(double youngs_modulus, double density) {
  FeModelBuilder builder;
  builder.add_node(1, {0.0, 0.0, 0.0});
  builder.add_node(2, {1.0, 0.0, 0.0});
  BeamProperty property = paper_rod_property();
  property.material.youngs_modulus = youngs_modulus;
  property.material.density = density;
  const int index = builder.add_beam_property(property, kWhere);
  return input_error_of([&] { builder.add_beam({{0, 1}, kZ, index}, kWhere); });
}

// A unit square plate (nodes 11..14) of paper steel with the thickness given.
std::string plate_error(double thickness) {
  FeModelBuilder builder;
  builder.add_node(11, {0.0, 0.0, 0.0});
  builder.add_node(12, {1.0, 0.0, 0.0});
  builder.add_node(13, {1.0, 1.0, 0.0});
  builder.add_node(14, {0.0, 1.0, 0.0});
  ShellProperty property;
  property.name = "plate";
  property.material = testing::paper_steel();
  property.thickness = thickness;
  const int index = builder.add_shell_property(property, kWhere);
  return input_error_of([&] { builder.add_shell({{0, 1, 2, 3}, index}, kWhere); });
}

TEST(FeModelBuilder, BeamMaterialAtExtremeMagnitudes) {
  // E = 1e-297 Pa: the axial stiffness E A / L = 2e-301 N/m, the first diagonal entry, is below
  // the range (printed to 6 digits, so the closed form is compared exactly as text).
  EXPECT_EQ(beam_error(1e-297, 7820.0),
            "case.yaml:12:5: beam 1-2 stiffness: expected diagonal entries within 1e-300 to 1e300 "
            "(SI units), got 2e-301 at ux at node 1; check E, nu and the section (A, Iy, Iz, J) "
            "against the length");
  // rho = 1e305 kg/m^3: the consistent axial mass rho A L / 3 = 6.66667e300 kg is above it.
  EXPECT_EQ(beam_error(206.8e9, 1e305),
            "case.yaml:12:5: beam 1-2 mass: expected diagonal entries within 1e-300 to 1e300 (SI "
            "units), got 6.66667e+300 at ux at node 1; check rho and the section (A, Iy, Iz) "
            "against the length");
  // E = 1e305 Pa: E A / L = 2e301 N/m is above it.
  EXPECT_NE(beam_error(1e305, 7820.0).find("stiffness: expected diagonal entries within 1e-300 "
                                           "to 1e300 (SI units), got 2e+301 at ux at node 1"),
            std::string::npos);
  // Far from both ends the beam is accepted: E 1e250 Pa and rho 1e-250 kg/m^3 give entries of
  // about 1e236 (12 E Iz / L^3) and 1e-262 (the torsional inertia rho J L / 3).
  EXPECT_EQ(beam_error(1e250, 1e-250), "no InputError");
}

TEST(FeModelBuilder, ShellThicknessAtExtremeMagnitudes) {
  // t = 1e-110 m: the rotary inertia rho t^3 / 12 per area underflows to 0 (the first diagonal
  // entry out of range; the rotations' stiffness keeps its transverse shear part, G t).
  EXPECT_EQ(plate_error(1e-110),
            "case.yaml:12:5: shell 11-12-13-14 mass: expected diagonal entries within 1e-300 to "
            "1e300 (SI units), got 0 at rx at node 11; check rho, the thickness and the "
            "non-structural mass against the size");
  // t = 1e120 m: the drilling inertia rho t^3 A / 12 ~ 1e363 overflows.
  EXPECT_NE(plate_error(1e120).find("shell 11-12-13-14 "), std::string::npos);
  EXPECT_EQ(plate_error(1e-60), "no InputError");
}

TEST(FeModelBuilder, PointMassAndSpringAtExtremeMagnitudes) {
  FeModelBuilder builder;
  builder.add_node(1, {0.0, 0.0, 0.0});
  PointMass m;
  m.node = 0;
  m.mass = 1e301;
  EXPECT_EQ(input_error_of([&] { builder.add_point_mass(m, kWhere); }),
            "case.yaml:12:5: point mass at node 1: expected diagonal entries within 1e-300 to "
            "1e300 (SI units), got 1e+301 at ux at node 1; check its mass and inertia");
  m.mass = 1.0;
  m.inertia = Eigen::Vector3d(1.0, 1.0, 1e-310).asDiagonal();  // a subnormal moment
  EXPECT_EQ(input_error_of([&] { builder.add_point_mass(m, kWhere); }),
            "case.yaml:12:5: point mass at node 1: expected diagonal entries within 1e-300 to "
            "1e300 (SI units), got 1e-310 at rz at node 1; check its mass and inertia");
  m.inertia = Eigen::Vector3d(1.0, 1.0, 0.0).asDiagonal();  // zero is allowed
  EXPECT_EQ(input_error_of([&] { builder.add_point_mass(m, kWhere); }), "no InputError");

  // A spring on ux and uy of node 1: k = 1e-310 N/m (subnormal) is refused, 0 and 1e300 are not.
  const auto spring = [&](double k) {
    return input_error_of([&] {
      builder.add_dof_stiffness({{0, 1}, Eigen::Vector2d(1.0, k).asDiagonal()}, "spring 7",
                                kWhere);
    });
  };
  EXPECT_EQ(spring(1e-310),
            "case.yaml:12:5: spring 7: expected diagonal entries within 1e-300 to 1e300 (SI "
            "units), got 1e-310 at uy at node 1; check its stiffness or mass values");
  EXPECT_EQ(spring(0.0), "no InputError");
  EXPECT_EQ(spring(1e300), "no InputError");
  EXPECT_NE(spring(2e300).find("got 2e+300 at uy at node 1"), std::string::npos);
}

}  // namespace
}  // namespace limber::fe
