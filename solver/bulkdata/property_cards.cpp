#include "bulkdata/property_cards.h"

#include <cmath>

#include "bulkdata/pbarl_section.h"

namespace limber::bulkdata {

namespace {

BeamPropertyCard beam_property(const CardFields& f) {
  BeamPropertyCard p;
  p.card = f.card().name;
  p.id = f.id(2, "PID");
  p.material = f.id(3, "MID");
  p.where = f.card().where();
  p.material_where = f.where(3);
  return p;
}

// K1, K2: shear factors; 0 means no shear deformation (both or neither).
void shear_factors(const CardFields& f, int field, double fallback, BeamPropertyCard& p) {
  const double k1 = f.real_or(field, "K1", fallback);
  const double k2 = f.real_or(field + 1, "K2", fallback);
  if (k1 < 0.0) f.fail(field, "K1", "expected a shear factor >= 0");
  if (k2 < 0.0) f.fail(field + 1, "K2", "expected a shear factor >= 0");
  if ((k1 == 0.0) != (k2 == 0.0)) {
    f.fail(field, "K1", fmt::format("expected K1 and K2 both 0 (or blank) or both > 0 (limber's "
                                    "beams are shear-flexible in both planes or in neither), "
                                    "got {} and {}",
                                    k1, k2));
  }
  p.timoshenko = k1 > 0.0;
  if (p.timoshenko) {
    p.section.shear_factor_y = k1;
    p.section.shear_factor_z = k2;
  }
}

// PELAS: up to two (PID, K, GE, S); PMASS: up to four (PID, M).
void scalar_properties(const CardFields& f, DeckState& state, int stride, int count, const char* value_name) {
  for (int k = 0; k < count; ++k) {
    const int field = 2 + stride * k;
    if (k > 0 && f.blank(field)) continue;
    ScalarPropertyCard p;
    p.card = f.card().name;
    p.id = f.id(field, "PID");
    p.value = f.real(field + 1, value_name);
    if (p.card == "PMASS" && !(p.value >= 0.0)) f.fail(field + 1, value_name, "expected a mass >= 0");
    p.where = f.card().where();
    if (state.property_ids.contains(p.id)) {
      f.fail(field, "PID", fmt::format("expected a unique property id, got {} again (first at {})",
                                       p.id, state.property_ids.at(p.id).to_string()));
    }
    state.property_ids.emplace(p.id, p.where);
    state.deck.scalar_properties.emplace(p.id, std::move(p));
  }
}

}  // namespace

void parse_mat1(const CardFields& f, DeckState& state) {
  MaterialCard m;
  m.id = f.id(2, "MID");
  m.material.name = "MAT1 " + std::to_string(m.id);
  const std::optional<double> e = f.optional_real(3, "E");
  const std::optional<double> g = f.optional_real(4, "G");
  const std::optional<double> nu = f.optional_real(5, "NU");
  if (e && !(*e > 0.0)) f.fail(3, "E", fmt::format("expected a value > 0, got {}", *e));
  if (g && !(*g > 0.0)) f.fail(4, "G", fmt::format("expected a value > 0, got {}", *g));
  // Two of E, G, nu fix the third through G = E / (2 (1 + nu)).
  if (e && nu) {
    m.material.youngs_modulus = *e;
    m.material.poisson_ratio = *nu;
    if (g) {
      const double derived = *e / (2.0 * (1.0 + *nu));
      // Decks round G; 1 % tells a rounded G from a different (e.g. orthotropic) one.
      if (!(std::abs(derived - *g) <= 0.01 * *g)) {
        f.fail(4, "G", fmt::format("expected G = E / (2 (1 + NU)) = {:.6g} within 1 % (limber's "
                                   "materials are isotropic), got {:.6g}",
                                   derived, *g));
      }
    }
  } else if (e && g) {
    m.material.youngs_modulus = *e;
    m.material.poisson_ratio = *e / (2.0 * *g) - 1.0;
  } else if (g && nu) {
    m.material.youngs_modulus = 2.0 * (1.0 + *nu) * *g;
    m.material.poisson_ratio = *nu;
  } else {
    f.fail_card("expected two of E (field 3), G (field 4) and NU (field 5), got fewer "
                "(limber derives the third from G = E / (2 (1 + NU)))");
  }
  const double poisson = m.material.poisson_ratio;
  if (!(poisson > -1.0 && poisson < 0.5)) {
    f.fail(nu ? 5 : 4, nu ? "NU" : "G",
           fmt::format("expected a Poisson ratio -1 < NU < 0.5, got {:.6g}", poisson));
  }
  m.material.density = f.real_or(6, "RHO", 0.0);
  if (!(m.material.density >= 0.0)) f.fail(6, "RHO", "expected a density >= 0");
  m.where = f.card().where();
  insert_unique(state.deck.materials, std::move(m), f, "MAT1");
}

void parse_pbar(const CardFields& f, DeckState& state) {
  BeamPropertyCard p = beam_property(f);
  p.section.area = positive(f, 4, "A");
  // I1 bends in plane 1 (local x-y, about z), I2 in plane 2.
  p.section.inertia_z = positive(f, 5, "I1");
  p.section.inertia_y = positive(f, 6, "I2");
  p.section.torsion_constant = positive(f, 7, "J");
  demand_zero(f, 8, "NSM", "non-structural mass on beams is");
  // Blank K1, K2 on PBAR: no shear deformation (NASTRAN's default).
  shear_factors(f, 22, 0.0, p);
  demand_zero(f, 24, "I12", "a product of inertia (unsymmetric section) is");
  insert_unique(state.deck.beam_properties, std::move(p), f, "property", &state.property_ids);
}

void parse_pbarl(const CardFields& f, DeckState& state) {
  BeamPropertyCard p = beam_property(f);
  const std::string group = f.blank(4) ? "MSCBML0" : f.text(4);
  if (group != "MSCBML0") f.fail(4, "GROUP", "expected MSCBML0 (the built-in library), got " + group);
  const std::string type = f.text(5);
  const int count = pbarl_dimension_count(type);
  if (count == 0) {
    f.fail(5, "TYPE", fmt::format("expected a PBARL type ROD, TUBE, BAR, BOX, I, CHAN, T or HAT, "
                                  "got '{}' (give other sections as PBAR)",
                                  type));
  }
  // DIM1..DIMn from field 12 on (markers skipped), then NSM.
  std::vector<double> dims;
  int field = 12;
  for (int i = 1; i <= count; ++i, ++field) {
    if (field % 10 == 0) field += 2;
    dims.push_back(positive(f, field, fmt::format("DIM{}", i).c_str()));
  }
  if (field % 10 == 0) field += 2;
  demand_zero(f, field, "NSM", "non-structural mass on beams is");
  std::string error;
  p.section = pbarl_section(type, dims, error);
  if (!error.empty()) f.fail(12, "DIM1", error);
  insert_unique(state.deck.beam_properties, std::move(p), f, "property", &state.property_ids);
}

// PBEAM with a constant section: line 1 (A end), optional stress points, optional stations
// that repeat the A end, and the optional K1.../M1... lines.
void parse_pbeam(const CardFields& f, DeckState& state) {
  BeamPropertyCard p = beam_property(f);
  p.section.area = positive(f, 4, "A");
  p.section.inertia_z = positive(f, 5, "I1");
  p.section.inertia_y = positive(f, 6, "I2");
  demand_zero(f, 7, "I12", "a product of inertia (unsymmetric section) is");
  p.section.torsion_constant = positive(f, 8, "J");
  demand_zero(f, 9, "NSM", "non-structural mass on beams is");

  const int lines = (f.last_field() - 1) / 10 + 1;
  const auto line_start = [](int line) { return 10 * line + 2; };  // its first data field
  const auto is_station = [&](int line) {
    const std::string& so = f.text(line_start(line));
    return so == "YES" || so == "YESA" || so == "NO";
  };
  int line = 1;
  if (line < lines && !is_station(line)) ++line;  // stress points of end A: not used
  while (line < lines && is_station(line)) {
    // A station must repeat the A end (blank fields do).
    const int start = line_start(line);
    const char* names[] = {"A", "I1", "I2", "I12", "J", "NSM"};
    const double a_end[] = {p.section.area, p.section.inertia_z, p.section.inertia_y, 0.0,
                            p.section.torsion_constant, 0.0};
    for (int k = 0; k < 6; ++k) {
      const std::optional<double> value = f.optional_real(start + 2 + k, names[k]);
      if (value && std::abs(*value - a_end[k]) > 1e-12 * std::abs(a_end[k])) {
        f.fail(start + 2 + k, names[k],
               fmt::format("expected the A-end value {} (tapered PBEAM is not supported), got {}",
                           a_end[k], *value));
      }
    }
    line += f.text(start) == "YES" ? 2 : 1;  // YES: a line of stress points follows
  }
  if (lines - line > 2) {
    f.fail(line_start(line), "K1",
           "expected at most the K1 and M1 lines after the stations, got more lines");
  }
  if (line < lines) {
    const int start = line_start(line);
    // Blank K1, K2 on PBEAM: shear area factor 1.0 (NASTRAN's default).
    shear_factors(f, start, 1.0, p);
    demand_zero(f, start + 2, "S1", "shear relief is");
    demand_zero(f, start + 3, "S2", "shear relief is");
    demand_zero(f, start + 4, "NSI(A)", "non-structural inertia is");
    demand_zero(f, start + 5, "NSI(B)", "non-structural inertia is");
    demand_zero(f, start + 6, "CW(A)", "warping is");
    demand_zero(f, start + 7, "CW(B)", "warping is");
    ++line;
  } else {
    // No K line: NASTRAN's default shear area factors K1 = K2 = 1.0.
    p.timoshenko = true;
    p.section.shear_factor_y = p.section.shear_factor_z = 1.0;
  }
  if (line < lines) {
    const int start = line_start(line);
    for (int k = 0; k < 8; ++k) demand_zero(f, start + k, "M/N", "a mass or neutral-axis offset is");
  }
  insert_unique(state.deck.beam_properties, std::move(p), f, "property", &state.property_ids);
}

void parse_pshell(const CardFields& f, DeckState& state) {
  ShellPropertyCard p;
  p.id = f.id(2, "PID");
  p.where = f.card().where();
  p.material_where = f.where(3);
  if (f.blank(3)) f.fail(3, "MID1", "expected a membrane material (a shell without membrane stiffness is not supported)");
  p.material = f.id(3, "MID1");
  p.thickness = positive(f, 4, "T");
  // Bending and shear from the same material as the membrane.
  if (f.blank(5)) f.fail(5, "MID2", "expected a bending material (membrane-only shells are not supported)");
  if (f.integer(5, "MID2") != p.material) {
    f.fail(5, "MID2", fmt::format("expected MID1's material {} (limber's shells have one "
                                  "material), got {}", p.material, f.text(5)));
  }
  p.bending_ratio = f.blank(6) ? 1.0 : positive(f, 6, "12I/T**3");
  if (f.blank(7)) {
    p.no_shear_material = true;
  } else if (f.integer(7, "MID3") != p.material) {
    f.fail(7, "MID3", fmt::format("expected MID1's material {} or blank, got {}", p.material,
                                  f.text(7)));
  }
  p.shear_ratio = f.blank(8) ? fe::kShellShearFactor : positive(f, 8, "TS/T");
  p.nonstructural_mass = f.real_or(9, "NSM", 0.0);
  if (!(p.nonstructural_mass >= 0.0)) f.fail(9, "NSM", "expected a value >= 0");
  if (!f.blank(14)) f.fail(14, "MID4", "expected blank (membrane-bending coupling is not supported)");
  insert_unique(state.deck.shell_properties, std::move(p), f, "property", &state.property_ids);
}

void parse_pelas(const CardFields& f, DeckState& state) { scalar_properties(f, state, 4, 2, "K"); }

void parse_pmass(const CardFields& f, DeckState& state) { scalar_properties(f, state, 2, 4, "M"); }

void parse_pbush(const CardFields& f, DeckState& state) {
  BushPropertyCard p;
  p.id = f.id(2, "PID");
  p.where = f.card().where();
  bool stiffness = false;
  // Lines led by a keyword in field 3, 13, 23, ... with six values after it.
  for (int key = 3; key <= f.last_field(); key += 10) {
    if (f.blank(key)) continue;
    const std::string& word = f.text(key);
    if (word == "K") {
      stiffness = true;
      const char* names[] = {"K1", "K2", "K3", "K4", "K5", "K6"};
      for (int k = 0; k < 6; ++k) {
        p.stiffness[static_cast<std::size_t>(k)] = f.real_or(key + 1 + k, names[k], 0.0);
        if (p.stiffness[static_cast<std::size_t>(k)] < 0.0) f.fail(key + 1 + k, names[k], "expected a stiffness >= 0");
      }
    } else if (word == "B" || word == "GE") {
      state.deck.parse_notices.push_back(fmt::format(
          "PBUSH {} ({}:{}): {} (damping) left out: damping is modal, in the case file", p.id,
          p.where.file, p.where.line, word));
    } else if (word != "RCV") {
      f.fail(key, "keyword", fmt::format("expected K, B, GE or RCV (other PBUSH lines are not "
                                         "supported), got '{}'", word));
    }
  }
  if (!stiffness) f.fail(3, "K", "expected a K line with K1-K6");
  insert_unique(state.deck.bush_properties, std::move(p), f, "property", &state.property_ids);
}

void parse_prod(const CardFields& f, DeckState& state) {
  RodPropertyCard p;
  p.id = f.id(2, "PID");
  p.material = f.id(3, "MID");
  rod_section(f, 4, p.area, p.torsion_constant, p.nonstructural_mass);
  p.where = f.card().where();
  p.material_where = f.where(3);
  insert_unique(state.deck.rod_properties, std::move(p), f, "property", &state.property_ids);
}

}  // namespace limber::bulkdata
