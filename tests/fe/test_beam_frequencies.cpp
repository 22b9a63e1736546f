// Natural frequencies of beam models against closed forms: the seed paper's steel rod
// (1 m, 0.01 x 0.02 m, 100 elements) in bending, extension and torsion, cantilevered and
// free-free, and a thick Timoshenko beam simply supported. Dense generalized eigen-solver
// on the free DOFs (at most 606 of them).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "fe/assembly.h"
#include "fe/beam_section.h"
#include "fe/fe_model_builder.h"
#include "fe/mesh_generators.h"
#include "fe_test_support.h"

namespace limber::fe {
namespace {

using testing::dense_frequencies;
using testing::paper_rod_property;
using testing::paper_steel;
using testing::relative_error;

constexpr double kPi = std::numbers::pi;
constexpr double kLength = 1.0;  // [m]
constexpr int kElements = 100;

// The rod along global x with local axes = global axes (orientation +y): bending in x-y
// uses Iz (weak, 0.02 * 0.01^3 / 12), bending in x-z uses Iy (strong, 0.01 * 0.02^3 / 12).
// Only the `active` DOFs stay free at every node; `clamp` also fixes node 0 entirely.
struct Rod {
  FeModelBuilder builder;
  std::vector<int> nodes;
};

Rod make_rod(const BeamProperty& property, const std::vector<Dof>& active, bool clamp,
             int elements = kElements, double length = kLength) {
  Rod rod;
  StraightBeamMesh mesh;
  mesh.end = Eigen::Vector3d(length, 0.0, 0.0);
  mesh.elements = elements;
  mesh.orientation = Eigen::Vector3d::UnitY();
  mesh.property = rod.builder.add_beam_property(property);
  rod.nodes = add_straight_beam(rod.builder, mesh);
  for (int node : rod.nodes) {
    for (int d = 0; d < kDofsPerNode; ++d) {
      const bool is_active = std::find(active.begin(), active.end(), Dof{d}) != active.end();
      if (!is_active || (clamp && node == rod.nodes.front())) rod.builder.fix(node, Dof{d});
    }
  }
  return rod;
}

const std::vector<Dof> kPlaneXy{Dof::kUy, Dof::kRz};
const std::vector<Dof> kPlaneXz{Dof::kUz, Dof::kRy};
const std::vector<Dof> kAllDofs{Dof::kUx, Dof::kUy, Dof::kUz, Dof::kRx, Dof::kRy, Dof::kRz};

// beta_n L of the Euler-Bernoulli frequency equations, as tabulated (Blevins, "Formulas for
// Natural Frequency and Mode Shape", 1979, table 8-1): cos cosh = -1 (cantilever) and
// cos cosh = +1 (free-free, elastic roots).
constexpr double kCantileverBetaL[] = {1.8751, 4.6941, 7.8548, 10.9955, 14.1372};
constexpr double kFreeFreeBetaL[] = {4.7300, 7.8532, 10.9956, 14.1372, 17.2788};

// Euler-Bernoulli omega_n = (beta_n L)^2 sqrt(E I / (rho A)) / L^2 [rad/s].
double euler_bernoulli_omega(double beta_l, double inertia) {
  const Material steel = paper_steel();
  const double area = 0.01 * 0.02;
  return beta_l * beta_l * std::sqrt(steel.youngs_modulus * inertia / (steel.density * area)) /
         (kLength * kLength);
}

// Root of cos(x) cosh(x) = sign nearest `guess`, by Newton on cos x - sign / cosh x.
double frequency_equation_root(double guess, double sign) {
  double x = guess;
  for (int i = 0; i < 50; ++i) {
    const double g = std::cos(x) - sign / std::cosh(x);
    const double dg = -std::sin(x) + sign * std::sinh(x) / (std::cosh(x) * std::cosh(x));
    x -= g / dg;
  }
  return x;
}

// R = int phi'^2 / int phi^2 over the beam for the exact Euler-Bernoulli mode of root
// beta L (Blevins table 8-1 shapes), by composite Simpson with 4000 intervals.
double slope_ratio(double beta_l, bool cantilever) {
  const double b = beta_l / kLength;
  const double sigma =
      cantilever ? (std::cosh(beta_l) + std::cos(beta_l)) / (std::sinh(beta_l) + std::sin(beta_l))
                 : (std::cosh(beta_l) - std::cos(beta_l)) / (std::sinh(beta_l) - std::sin(beta_l));
  const auto phi = [&](double x) {
    const double s = b * x;
    return cantilever ? std::cosh(s) - std::cos(s) - sigma * (std::sinh(s) - std::sin(s))
                      : std::cosh(s) + std::cos(s) - sigma * (std::sinh(s) + std::sin(s));
  };
  const auto dphi = [&](double x) {
    const double s = b * x;
    return b * (cantilever ? std::sinh(s) + std::sin(s) - sigma * (std::cosh(s) - std::cos(s))
                           : std::sinh(s) - std::sin(s) - sigma * (std::cosh(s) + std::cos(s)));
  };
  constexpr int kIntervals = 4000;
  const double h = kLength / kIntervals;
  double slope = 0.0;
  double value = 0.0;
  for (int i = 0; i <= kIntervals; ++i) {
    const double w = (i == 0 || i == kIntervals) ? 1.0 : (i % 2 == 1 ? 4.0 : 2.0);
    const double x = i * h;
    slope += w * dphi(x) * dphi(x);
    value += w * phi(x) * phi(x);
  }
  return slope / value;
}

// Elastic frequencies: drops the first `rigid` entries.
std::vector<double> elastic(const std::vector<double>& omega, int rigid) {
  return {omega.begin() + rigid, omega.end()};
}

struct PlaneCase {
  const char* name;
  const std::vector<Dof>* active;
  double inertia;
};

std::vector<PlaneCase> plane_cases() {
  const BeamSection section = rectangle_section(0.01, 0.02);
  return {{"x-y (Iz)", &kPlaneXy, section.inertia_z}, {"x-z (Iy)", &kPlaneXz, section.inertia_y}};
}

TEST(BeamFrequencies, TabulatedRootsSolveTheFrequencyEquations) {
  // The 5-digit table values are the roots rounded: |error| <= 5e-5 (half the last digit).
  for (int n = 0; n < 5; ++n) {
    EXPECT_NEAR(frequency_equation_root(kCantileverBetaL[n], -1.0), kCantileverBetaL[n], 5e-5);
    EXPECT_NEAR(frequency_equation_root(kFreeFreeBetaL[n], 1.0), kFreeFreeBetaL[n], 5e-5);
  }
}

TEST(BeamFrequencies, PaperRodBendingMatchesEulerBernoulli) {
  // Pure Euler-Bernoulli element (no section rotary inertia) against the Euler-Bernoulli
  // closed form, first 5 bending modes of each plane, cantilever and free-free.
  // 0.05 % holds because what remains is (a) the rounding of the tabulated beta L (5 digits:
  // <= 5.3e-5 relative on (beta L)^2) and (b) the Hermite-cubic discretisation error, of
  // order (beta h)^4 / 720 < 1e-7 for beta h <= 0.17 (100 elements). With the section's rotary
  // inertia kept (the default), frequencies drop by about r^2 int phi'^2 / (2 int phi^2), up to
  // 0.66 % for the 5th free-free x-z mode of this rod: that is checked in the next test.
  const BeamProperty property = paper_rod_property(false, /*rotary_inertia=*/false);
  double worst = 0.0;
  for (const PlaneCase& plane : plane_cases()) {
    const std::vector<double> cantilever =
        dense_frequencies(std::move(make_rod(property, *plane.active, true).builder).build());
    const std::vector<double> free_free = elastic(
        dense_frequencies(std::move(make_rod(property, *plane.active, false).builder).build()), 2);
    for (int n = 0; n < 5; ++n) {
      const double c =
          relative_error(cantilever[n], euler_bernoulli_omega(kCantileverBetaL[n], plane.inertia));
      const double f =
          relative_error(free_free[n], euler_bernoulli_omega(kFreeFreeBetaL[n], plane.inertia));
      EXPECT_LT(c, 5e-4) << plane.name << " cantilever mode " << n + 1;
      EXPECT_LT(f, 5e-4) << plane.name << " free-free mode " << n + 1;
      worst = std::max({worst, c, f});
    }
  }
  std::printf("[ measured ] worst bending error vs Euler-Bernoulli: %.3e\n", worst);
}

TEST(BeamFrequencies, RotaryInertiaLowersBendingAsTheRayleighQuotient) {
  // Second method: the Rayleigh quotient of the exact Euler-Bernoulli mode with the
  // section's rotary inertia added to the kinetic energy,
  //   omega^2 = omega_EB^2 / (1 + r^2 R),  r^2 = I / A,  R = int phi'^2 / int phi^2.
  // Its error is second order in the mode-shape change, i.e. O((r^2 R)^2) <= 1e-4 here
  // (r^2 R <= 1e-2 for the 5th free-free x-z mode); the tolerance is (r^2 R)^2 per mode plus
  // the 1e-6 of discretisation (previous test), exact roots used.
  const BeamProperty property = paper_rod_property();
  const double area = property.section.area;
  for (const PlaneCase& plane : plane_cases()) {
    const double r2 = plane.inertia / area;
    for (const bool clamp : {true, false}) {
      const std::vector<double> omega = elastic(
          dense_frequencies(std::move(make_rod(property, *plane.active, clamp).builder).build()),
          clamp ? 0 : 2);
      for (int n = 0; n < 5; ++n) {
        const double beta_l = frequency_equation_root(
            clamp ? kCantileverBetaL[n] : kFreeFreeBetaL[n], clamp ? -1.0 : 1.0);
        const double shift = r2 * slope_ratio(beta_l, clamp);
        const double reference =
            euler_bernoulli_omega(beta_l, plane.inertia) / std::sqrt(1.0 + shift);
        EXPECT_LT(relative_error(omega[n], reference), shift * shift + 1e-6)
            << plane.name << (clamp ? " cantilever" : " free-free") << " mode " << n + 1;
        std::printf(
            "[ measured ] %s %s mode %d: rotary-inertia drop %.3e, error vs Rayleigh %.3e\n",
            plane.name, clamp ? "cantilever" : "free-free", n + 1,
            1.0 - omega[n] / euler_bernoulli_omega(beta_l, plane.inertia),
            relative_error(omega[n], reference));
      }
    }
  }
}

TEST(BeamFrequencies, AxialFixedFreeMatchesClosedForm) {
  // omega_n = (2n - 1) pi / 2 sqrt(E / rho) / L. Linear elements with consistent mass
  // over-estimate by about (omega h / c)^2 / 24 <= 2.5e-4 for n <= 3: 0.1 % holds.
  const Material steel = paper_steel();
  const std::vector<double> omega = dense_frequencies(
      std::move(make_rod(paper_rod_property(), {Dof::kUx}, true).builder).build());
  for (int n = 1; n <= 3; ++n) {
    const double reference =
        (2 * n - 1) * kPi / 2.0 * std::sqrt(steel.youngs_modulus / steel.density) / kLength;
    EXPECT_LT(relative_error(omega[n - 1], reference), 1e-3) << "mode " << n;
    std::printf("[ measured ] axial mode %d error %.3e\n", n,
                relative_error(omega[n - 1], reference));
  }
}

TEST(BeamFrequencies, TorsionFixedFreeMatchesClosedForm) {
  // omega_n = (2n - 1) pi / (2 L) sqrt(G J / (rho Ip)), Ip = Iy + Iz; same linear
  // interpolation as the axial case, hence the same 0.1 % bound.
  const BeamProperty property = paper_rod_property();
  const BeamSection& s = property.section;
  const Material& steel = property.material;
  const std::vector<double> omega =
      dense_frequencies(std::move(make_rod(property, {Dof::kRx}, true).builder).build());
  for (int n = 1; n <= 3; ++n) {
    const double reference = (2 * n - 1) * kPi / (2.0 * kLength) *
                             std::sqrt(steel.shear_modulus() * s.torsion_constant /
                                       (steel.density * (s.inertia_y + s.inertia_z)));
    EXPECT_LT(relative_error(omega[n - 1], reference), 1e-3) << "mode " << n;
    std::printf("[ measured ] torsion mode %d error %.3e\n", n,
                relative_error(omega[n - 1], reference));
  }
}

TEST(BeamFrequencies, FreeFreeRodHasSixRigidModesAndDecoupledSpectrum) {
  // Full 3D model, 606 free DOFs: exactly 6 frequencies near zero (below 1 rad/s, i.e.
  // < 0.3 % of the first elastic one, 332 rad/s; round-off gives ~1e-2 rad/s), then the
  // union of the planar, axial and torsional spectra of the same rod: a straight beam along
  // a principal axis couples none of them, so the two methods agree to round-off (1e-8).
  const BeamProperty property = paper_rod_property();
  const std::vector<double> full =
      dense_frequencies(std::move(make_rod(property, kAllDofs, false).builder).build());
  ASSERT_EQ(full.size(), 606u);
  int near_zero = 0;
  for (double w : full) near_zero += std::abs(w) < 1.0 ? 1 : 0;
  EXPECT_EQ(near_zero, 6);
  EXPECT_GT(full[6], 300.0);

  // Union of the decoupled spectra, rigid modes dropped (2 per plane, 1 axial, 1 torsion).
  std::vector<double> parts;
  const auto add = [&](const std::vector<Dof>& active, int rigid) {
    const std::vector<double> omega = elastic(
        dense_frequencies(std::move(make_rod(property, active, false).builder).build()), rigid);
    parts.insert(parts.end(), omega.begin(), omega.end());
  };
  add(kPlaneXy, 2);
  add(kPlaneXz, 2);
  add({Dof::kUx}, 1);
  add({Dof::kRx}, 1);
  std::sort(parts.begin(), parts.end());
  for (int i = 0; i < 30; ++i) {
    EXPECT_LT(relative_error(full[6 + i], parts[i]), 1e-8) << "elastic mode " << i + 1;
  }
}

// Timoshenko frequency equation of a simply supported beam with rotary inertia and shear
// (Timoshenko 1921; Han, Benaroya & Wei, J. Sound Vib. 225 (1999) 935, hinged-hinged case):
// with alpha = n pi / L, the lower root omega^2 of
//   (rho^2 I / (k G)) omega^4 - [rho A + rho I alpha^2 (1 + E / (k G))] omega^2 + E I alpha^4 = 0.
double timoshenko_simply_supported_omega(int n, const BeamProperty& p, double length,
                                         double inertia, double shear_factor) {
  const double e = p.material.youngs_modulus;
  const double g = p.material.shear_modulus();
  const double rho = p.material.density;
  const double area = p.section.area;
  const double alpha = n * kPi / length;
  const double a = rho * rho * inertia / (shear_factor * g);
  const double b = rho * area + rho * inertia * alpha * alpha * (1.0 + e / (shear_factor * g));
  const double c = e * inertia * std::pow(alpha, 4);
  const double lambda = (b - std::sqrt(b * b - 4.0 * a * c)) / (2.0 * a);
  return std::sqrt(lambda);
}

// Frequencies of the thick simply supported beam: L / h = 5, 1 m long, 0.1 m (y) x 0.2 m (z),
// Timoshenko, bending in x-z only, uz held at both ends.
std::vector<double> thick_simply_supported(int elements) {
  BeamProperty property = paper_rod_property(/*timoshenko=*/true);
  property.section = rectangle_section(0.1, 0.2);
  Rod rod = make_rod(property, kPlaneXz, false, elements, kLength);
  rod.builder.fix(rod.nodes.front(), Dof::kUz);
  rod.builder.fix(rod.nodes.back(), Dof::kUz);
  return dense_frequencies(std::move(rod.builder).build());
}

TEST(BeamFrequencies, ThickTimoshenkoBeamSimplySupportedMatchesClosedForm) {
  // The shear strain of the element is constant per element, so in dynamics its error is
  // O(h) in energy and the frequencies converge as h^2 (not h^4 as for Euler-Bernoulli).
  // Checked twice: at 100 elements the first 4 modes are within 0.05 % (measured <= 3.5e-4),
  // and halving h from L/50 divides each error by 4 +- 0.1 (h^2 order; measured 4.001), so the
  // element converges to the closed form and not to a nearby value. Euler-Bernoulli is 6-70 % off
  // for these modes, which shows that the check can fail.
  BeamProperty property = paper_rod_property(/*timoshenko=*/true);
  property.section = rectangle_section(0.1, 0.2);
  const double iy = property.section.inertia_y;
  const std::vector<double> coarse = thick_simply_supported(50);
  const std::vector<double> fine = thick_simply_supported(100);
  for (int n = 1; n <= 4; ++n) {
    const double reference = timoshenko_simply_supported_omega(n, property, kLength, iy,
                                                               property.section.shear_factor_z);
    const double euler_bernoulli = std::pow(n * kPi / kLength, 2) *
                                   std::sqrt(property.material.youngs_modulus * iy /
                                             (property.material.density * property.section.area));
    const double error_fine = relative_error(fine[n - 1], reference);
    const double ratio = relative_error(coarse[n - 1], reference) / error_fine;
    EXPECT_LT(error_fine, 5e-4) << "mode " << n;
    EXPECT_NEAR(ratio, 4.0, 0.1) << "mode " << n;
    EXPECT_GT(relative_error(fine[n - 1], euler_bernoulli), 0.05) << "mode " << n;
    std::printf(
        "[ measured ] Timoshenko SS mode %d: error %.3e, h-halving ratio %.3f "
        "(Euler-Bernoulli off by %.3e)\n",
        n, error_fine, ratio, relative_error(euler_bernoulli, reference));
  }
}

}  // namespace
}  // namespace limber::fe
