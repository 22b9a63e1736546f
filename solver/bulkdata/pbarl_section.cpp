#include "bulkdata/pbarl_section.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "fe/beam_section.h"
#include "fe/section_outline.h"

namespace limber::bulkdata {

namespace {

// A rectangle of a thin-walled section: extent along local z (width) and y (height), centre.
struct Rectangle {
  double width_z = 0.0, height_y = 0.0, z = 0.0, y = 0.0;
};

// A, I1 (about z through the centroid), I2 (about y), the extreme fibres, and the open
// thin-walled torsion constant J = sum b t^3 / 3 (b the longer side, t the shorter) of a
// section made of rectangles (sections symmetric about y, so I12 = 0).
fe::BeamSection composite_section(const std::vector<Rectangle>& parts) {
  fe::BeamSection section;
  double a = 0.0, ay = 0.0, az = 0.0;
  for (const Rectangle& r : parts) {
    const double area = r.width_z * r.height_y;
    a += area;
    ay += area * r.y;
    az += area * r.z;
  }
  const double yc = ay / a, zc = az / a;
  double i1 = 0.0, i2 = 0.0, j = 0.0, fibre_y = 0.0, fibre_z = 0.0;
  for (const Rectangle& r : parts) {
    const double area = r.width_z * r.height_y;
    // Parallel axes (Steiner) about the centroid.
    i1 += r.width_z * r.height_y * r.height_y * r.height_y / 12.0 + area * (r.y - yc) * (r.y - yc);
    i2 += r.height_y * r.width_z * r.width_z * r.width_z / 12.0 + area * (r.z - zc) * (r.z - zc);
    const double longer = std::max(r.width_z, r.height_y), shorter = std::min(r.width_z, r.height_y);
    j += longer * shorter * shorter * shorter / 3.0;
    fibre_y = std::max(fibre_y, std::abs(r.y - yc) + 0.5 * r.height_y);
    fibre_z = std::max(fibre_z, std::abs(r.z - zc) + 0.5 * r.width_z);
  }
  section.area = a;
  section.inertia_z = i1;
  section.inertia_y = i2;
  section.torsion_constant = j;
  section.fibre_y = fibre_y;
  section.fibre_z = fibre_z;
  return section;
}

// ROD: a solid circle of radius DIM1.
fe::BeamSection rod_section(const std::vector<double>& dims, std::string&) {
  constexpr double pi = std::numbers::pi;
  fe::BeamSection section;
  const double r = dims[0];
  section.area = pi * r * r;
  section.inertia_y = section.inertia_z = pi * r * r * r * r / 4.0;
  section.torsion_constant = 2.0 * section.inertia_y;
  section.outline = fe::circle_outline(2.0 * r);
  return section;
}

// TUBE: a circular tube, outer radius DIM1, inner radius DIM2.
fe::BeamSection tube_section(const std::vector<double>& dims, std::string& error) {
  constexpr double pi = std::numbers::pi;
  fe::BeamSection section;
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
  section.outline = fe::tube_outline(2.0 * ro, 2.0 * ri);
  return section;
}

// BAR: a solid rectangle.
fe::BeamSection bar_section(const std::vector<double>& dims, std::string&) {
  // DIM2 along local y, DIM1 along local z.
  return fe::rectangle_section(dims[1], dims[0]);
}

// BOX: a rectangular tube; J of a thin-walled closed section (Bredt).
fe::BeamSection box_section(const std::vector<double>& dims, std::string& error) {
  fe::BeamSection section;
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
  // Height h along y with walls t1 across it; width b along z with walls t2.
  section.outline = fe::box_outline(h, b, t1, t2);
  return section;
}

// I: two flanges and a web, three rectangles.
fe::BeamSection i_section(const std::vector<double>& dims, std::string& error) {
  // Height h = DIM1 along y; bottom flange DIM2 x DIM5, top flange DIM3 x DIM6, web DIM4.
  const double h = dims[0], bottom = dims[1], top = dims[2], web = dims[3], tb = dims[4], tt = dims[5];
  const double web_height = h - tb - tt;
  if (!(web_height > 0.0 && web < std::min(bottom, top))) {
    error = fmt::format("expected flanges thinner than the height (DIM5 + DIM6 < DIM1) and a web "
                        "narrower than both flanges (DIM4 < DIM2, DIM3), got a web {} x {}",
                        web, web_height);
    return {};
  }
  fe::BeamSection section = composite_section({{bottom, tb, 0.0, 0.5 * tb},
                               {web, web_height, 0.0, tb + 0.5 * web_height},
                               {top, tt, 0.0, h - 0.5 * tt}});
  // (y, z) corners of the same three rectangles, bottom flange first.
  section.outline = fe::centred_polygon(
      {{0.0, -0.5 * bottom}, {0.0, 0.5 * bottom}, {tb, 0.5 * bottom}, {tb, 0.5 * web},
       {h - tt, 0.5 * web}, {h - tt, 0.5 * top}, {h, 0.5 * top}, {h, -0.5 * top},
       {h - tt, -0.5 * top}, {h - tt, -0.5 * web}, {tb, -0.5 * web}, {tb, -0.5 * bottom}});
  return section;
}

// CHAN: a web and two flanges on one side, three rectangles.
fe::BeamSection chan_section(const std::vector<double>& dims, std::string& error) {
  // Flange width DIM1 along z (web included), height DIM2 along y, web DIM3, flanges DIM4.
  const double b = dims[0], h = dims[1], web = dims[2], flange = dims[3];
  if (!(web < b && 2.0 * flange < h)) {
    error = fmt::format("expected a web thinner than the width (DIM3 < DIM1) and flanges thinner "
                        "than half the height (2 DIM4 < DIM2), got {} and {}",
                        web, flange);
    return {};
  }
  const double arm = b - web;  // flange outside the web
  fe::BeamSection section = composite_section({{web, h, 0.5 * web, 0.0},
                               {arm, flange, web + 0.5 * arm, 0.5 * (h - flange)},
                               {arm, flange, web + 0.5 * arm, -0.5 * (h - flange)}});
  // (y, z) corners: the web's back at z = 0, the flanges' tips at z = b.
  section.outline = fe::centred_polygon({{-0.5 * h, 0.0},
                                         {-0.5 * h, b},
                                         {-0.5 * h + flange, b},
                                         {-0.5 * h + flange, web},
                                         {0.5 * h - flange, web},
                                         {0.5 * h - flange, b},
                                         {0.5 * h, b},
                                         {0.5 * h, 0.0}});
  return section;
}

// T: a flange on a web, two rectangles.
fe::BeamSection t_section(const std::vector<double>& dims, std::string& error) {
  // Flange DIM1 (z) x DIM3 (y) on top of a web DIM4 wide; total height DIM2.
  const double b = dims[0], h = dims[1], flange = dims[2], web = dims[3];
  if (!(flange < h && web < b)) {
    error = fmt::format("expected a flange thinner than the height (DIM3 < DIM2) and a web "
                        "narrower than the flange (DIM4 < DIM1), got {} and {}",
                        flange, web);
    return {};
  }
  fe::BeamSection section = composite_section({{web, h - flange, 0.0, 0.5 * (h - flange)},
                               {b, flange, 0.0, h - 0.5 * flange}});
  // (y, z) corners: the web's foot at y = 0, the flange on top.
  section.outline = fe::centred_polygon({{0.0, -0.5 * web},
                                         {0.0, 0.5 * web},
                                         {h - flange, 0.5 * web},
                                         {h - flange, 0.5 * b},
                                         {h, 0.5 * b},
                                         {h, -0.5 * b},
                                         {h - flange, -0.5 * b},
                                         {h - flange, -0.5 * web}});
  return section;
}

// HAT: a crown, two walls and two brims, five rectangles.
fe::BeamSection hat_section(const std::vector<double>& dims, std::string& error) {
  // Height DIM1 (y), wall thickness DIM2 everywhere, crown width DIM3 (outer), brims DIM4.
  const double h = dims[0], t = dims[1], crown = dims[2], brim = dims[3];
  if (!(2.0 * t < crown && 2.0 * t < h)) {
    error = fmt::format("expected walls thinner than half the crown and the height (2 DIM2 < "
                        "DIM3, DIM1), got {}",
                        t);
    return {};
  }
  // Walls inside the crown's edges; each brim runs from under its wall to DIM4 beyond it.
  const double wall_z = 0.5 * crown - 0.5 * t, brim_z = 0.5 * crown + 0.5 * (brim - t);
  fe::BeamSection section = composite_section({{crown, t, 0.0, h - 0.5 * t},
                               {t, h - 2.0 * t, -wall_z, 0.5 * h},
                               {t, h - 2.0 * t, wall_z, 0.5 * h},
                               {brim + t, t, -brim_z, 0.5 * t},
                               {brim + t, t, brim_z, 0.5 * t}});
  // (y, z) corners: right brim, outer wall, crown, left wall and brim, then the inside.
  const double c = 0.5 * crown;
  section.outline = fe::centred_polygon({{0.0, c + brim},
                                         {t, c + brim},
                                         {t, c},
                                         {h, c},
                                         {h, -c},
                                         {t, -c},
                                         {t, -c - brim},
                                         {0.0, -c - brim},
                                         {0.0, -c + t},
                                         {h - t, -c + t},
                                         {h - t, c - t},
                                         {0.0, c - t}});
  return section;
}

// The PBARL types this reader knows (MSC Nastran Quick Reference Guide, PBARL), with their
// dimension counts and the section each makes.
struct PbarlType {
  const char* name;
  int dimension_count;
  fe::BeamSection (*section)(const std::vector<double>& dims, std::string& error);
};
constexpr PbarlType kPbarlTypes[] = {
    {"ROD", 1, rod_section}, {"TUBE", 2, tube_section}, {"BAR", 2, bar_section},
    {"BOX", 4, box_section}, {"I", 6, i_section},       {"CHAN", 4, chan_section},
    {"T", 4, t_section},     {"HAT", 4, hat_section},
};

const PbarlType* find_pbarl_type(const std::string& type) {
  for (const PbarlType& known : kPbarlTypes) {
    if (type == known.name) return &known;
  }
  return nullptr;
}

}  // namespace

int pbarl_dimension_count(const std::string& type) {
  const PbarlType* known = find_pbarl_type(type);
  return known ? known->dimension_count : 0;
}

fe::BeamSection pbarl_section(const std::string& type, const std::vector<double>& dims,
                              std::string& error) {
  error.clear();
  // Inertias go with a dimension's fourth power: it must be a normal double (dimensions from
  // about 1e-77 to 1e77 m). At 1e-170 m an I section's outline had no area and aborted on
  // fe::centred_polygon's DEMAND (issue 31).
  for (const double d : dims) {
    if (!std::isnormal(d * d * d * d)) {
      error = fmt::format("expected dimensions whose fourth powers (the inertias) are normal numbers, "
                          "about 1e-77 to 1e77, got {}",
                          d);
      return {};
    }
  }
  const PbarlType* known = find_pbarl_type(type);
  if (!known) {
    error = fmt::format("expected a PBARL type ROD, TUBE, BAR, BOX, I, CHAN, T or HAT, got '{}'", type);
    return {};
  }
  return known->section(dims, error);
}

}  // namespace limber::bulkdata
