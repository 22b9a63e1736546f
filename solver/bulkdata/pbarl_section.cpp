#include "bulkdata/pbarl_section.h"

#include <fmt/format.h>

#include <numbers>

#include "fe/beam_section.h"

namespace limber::bulkdata {

int pbarl_dimension_count(const std::string& type) {
  if (type == "ROD") return 1;
  if (type == "TUBE" || type == "BAR") return 2;
  if (type == "BOX") return 4;
  return 0;
}

fe::BeamSection pbarl_section(const std::string& type, const std::vector<double>& dims,
                              std::string& error) {
  constexpr double pi = std::numbers::pi;
  fe::BeamSection section;
  error.clear();
  if (type == "ROD") {
    const double r = dims[0];
    section.area = pi * r * r;
    section.inertia_y = section.inertia_z = pi * r * r * r * r / 4.0;
    section.torsion_constant = 2.0 * section.inertia_y;
  } else if (type == "TUBE") {
    const double ro = dims[0];
    const double ri = dims[1];
    if (!(ri < ro)) {
      error = fmt::format("expected an inner radius DIM2 below the outer radius DIM1, got {} >= {}",
                          ri, ro);
      return {};
    }
    section.area = pi * (ro * ro - ri * ri);
    section.inertia_y = section.inertia_z = pi * (ro * ro * ro * ro - ri * ri * ri * ri) / 4.0;
    section.torsion_constant = 2.0 * section.inertia_y;
  } else if (type == "BAR") {
    // DIM2 along local y, DIM1 along local z.
    section = fe::rectangle_section(dims[1], dims[0]);
  } else if (type == "BOX") {
    const double b = dims[0];
    const double h = dims[1];
    const double t1 = dims[2];
    const double t2 = dims[3];
    const double bi = b - 2.0 * t2;
    const double hi = h - 2.0 * t1;
    if (!(bi > 0.0 && hi > 0.0)) {
      error = fmt::format("expected walls thinner than half the box (2 DIM4 < DIM1, 2 DIM3 < "
                          "DIM2), got an inner box {} x {}",
                          bi, hi);
      return {};
    }
    section.area = b * h - bi * hi;
    section.inertia_z = (b * h * h * h - bi * hi * hi * hi) / 12.0;
    section.inertia_y = (h * b * b * b - hi * bi * bi * bi) / 12.0;
    section.torsion_constant = 2.0 * t1 * t2 * (b - t2) * (b - t2) * (h - t1) * (h - t1) /
                               (b * t2 + h * t1 - t2 * t2 - t1 * t1);
  } else {
    error = fmt::format("expected a PBARL type ROD, TUBE, BAR or BOX, got '{}'", type);
    return {};
  }
  return section;
}

}  // namespace limber::bulkdata
