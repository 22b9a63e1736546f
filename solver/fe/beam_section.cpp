#include "fe/beam_section.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "core/error.h"

namespace limber::fe {

namespace {

// Rejects sizes that are not strictly positive and finite.
void demand_positive_size(double value, const char* what) {
  if (!(value > 0.0) || !std::isfinite(value)) {
    throw InputError(fmt::format("{}: expected a positive finite size [m], got {}", what, value));
  }
}

}  // namespace

double rectangle_torsion_constant(double side_1, double side_2) {
  demand_positive_size(side_1, "rectangle side");
  demand_positive_size(side_2, "rectangle side");
  const double a = std::max(side_1, side_2);
  const double b = std::min(side_1, side_2);
  constexpr double kPi = std::numbers::pi;

  // Sum the odd-n series until a term no longer changes the sum (terms fall as n^-5).
  double sum = 0.0;
  for (int n = 1;; n += 2) {
    const double n5 = std::pow(static_cast<double>(n), 5);
    const double term = std::tanh(n * kPi * a / (2.0 * b)) / n5;
    sum += term;
    if (term < 1e-17 * sum) break;
  }
  return a * b * b * b * (1.0 / 3.0 - 64.0 / std::pow(kPi, 5) * (b / a) * sum);
}

BeamSection rectangle_section(double width_y, double height_z) {
  demand_positive_size(width_y, "rectangle section width (local y)");
  demand_positive_size(height_z, "rectangle section height (local z)");
  BeamSection section;
  section.area = width_y * height_z;
  section.inertia_y = width_y * std::pow(height_z, 3) / 12.0;
  section.inertia_z = height_z * std::pow(width_y, 3) / 12.0;
  section.torsion_constant = rectangle_torsion_constant(width_y, height_z);
  section.shear_factor_y = 5.0 / 6.0;
  section.shear_factor_z = 5.0 / 6.0;
  section.fibre_y = 0.5 * width_y;
  section.fibre_z = 0.5 * height_z;
  section.outline = rectangle_outline(width_y, height_z);
  return section;
}

BeamSection circle_section(double diameter, double poisson_ratio) {
  demand_positive_size(diameter, "circle section diameter");
  if (!(poisson_ratio > -1.0 && poisson_ratio < 0.5)) {
    throw InputError(
        fmt::format("circle section Poisson ratio: expected -1 < nu < 0.5, got {}", poisson_ratio));
  }
  constexpr double kPi = std::numbers::pi;
  const double d2 = diameter * diameter;
  BeamSection section;
  section.area = kPi * d2 / 4.0;
  section.inertia_y = kPi * d2 * d2 / 64.0;
  section.inertia_z = section.inertia_y;
  section.torsion_constant = kPi * d2 * d2 / 32.0;
  // Cowper 1966 shear coefficient of a solid circle.
  const double k = 6.0 * (1.0 + poisson_ratio) / (7.0 + 6.0 * poisson_ratio);
  section.shear_factor_y = k;
  section.shear_factor_z = k;
  section.fibre_y = 0.5 * diameter;
  section.fibre_z = 0.5 * diameter;
  section.circular = true;
  section.outline = circle_outline(diameter);
  return section;
}

}  // namespace limber::fe
