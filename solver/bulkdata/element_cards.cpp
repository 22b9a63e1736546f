#include "bulkdata/element_cards.h"

namespace limber::bulkdata {

namespace {

// CQUAD4 and CTRIA3: id, property (EID by default), N grids from field 4, ZOFFS at
// `offset_field`, no corner thicknesses (TFLAG and T1.. from field 13).
template <int N>
ShellCard<N> shell_card(const CardFields& f, int offset_field) {
  ShellCard<N> c;
  c.id = f.id(2, "EID");
  c.property = f.blank(3) ? c.id : f.id(3, "PID");
  const char* names[] = {"G1", "G2", "G3", "G4"};
  for (int k = 0; k < N; ++k) {
    c.grids[k] = f.id(4 + k, names[k]);
    c.grid_where[k] = f.where(4 + k);
  }
  c.where = f.card().where();
  c.property_where = f.where(3);
  demand_zero(f, offset_field, "ZOFFS", "a shell offset is");
  if (!f.blank(13)) f.fail(13, "TFLAG", "expected blank (corner thicknesses are not supported)");
  const char* corners[] = {"T1", "T2", "T3", "T4"};
  for (int k = 0; k < N; ++k) {
    if (!f.blank(14 + k)) {
      f.fail(14 + k, corners[k],
             "expected blank (corner thicknesses are not supported: PSHELL's T is used)");
    }
  }
  return c;
}

}  // namespace

void parse_cbar(const CardFields& f, DeckState& state) {
  BeamCard b;
  b.card = f.card().name;
  b.id = f.id(2, "EID");
  b.property = f.blank(3) ? b.id : f.id(3, "PID");
  b.grids = {f.id(4, "GA"), f.id(5, "GB")};
  b.where = f.card().where();
  b.property_where = f.where(3);
  b.grid_where = {f.where(4), f.where(5)};
  b.orientation_where = f.where(6);
  // Orientation: G0 (an integer) or X1-X3 (reals).
  if (f.blank(6)) f.fail(6, "X1/G0", "expected an orientation vector or a grid G0, got blank (BAROR defaults are not supported)");
  if (f.is_integer(6)) {
    b.orientation_grid = f.id(6, "G0");
    if (!f.blank(7) || !f.blank(8)) f.fail(7, "X2", "expected blank after G0");
  } else {
    b.orientation = {f.real(6, "X1"), f.real_or(7, "X2", 0.0), f.real_or(8, "X3", 0.0)};
  }
  // OFFT: the vector in GA's displacement system (G..) or in basic (B..).
  const bool beam = b.card == "CBEAM";
  if (!f.blank(9) && !(beam && parse_real(f.text(9)))) {
    const std::string& offt = f.text(9);
    if (offt.size() != 3 || (offt[0] != 'G' && offt[0] != 'B')) {
      f.fail(9, "OFFT", fmt::format("expected GGG, BGG, GGO, ... got '{}'", offt));
    }
    b.orientation_in_basic = offt[0] == 'B';
  } else if (beam) {
    demand_zero(f, 9, "BIT", "a built-in twist is");
  }
  // Pin flags and offsets change the element: not supported.
  if (f.integer_or(12, "PA", 0) != 0) f.fail(12, "PA", "expected blank (pin flags are not supported)");
  if (f.integer_or(13, "PB", 0) != 0) f.fail(13, "PB", "expected blank (pin flags are not supported)");
  const char* offsets[] = {"W1A", "W2A", "W3A", "W1B", "W2B", "W3B"};
  for (int k = 0; k < 6; ++k) demand_zero(f, 14 + k, offsets[k], "an end offset is");
  if (beam && (!f.blank(22) || !f.blank(23))) {
    f.fail(22, "SA", "expected blank (warping scalar points are not supported)");
  }
  insert_unique(state.deck.beams, std::move(b), f, "element", &state.element_ids);
}

void parse_cquad4(const CardFields& f, DeckState& state) {
  insert_unique(state.deck.quads, shell_card<4>(f, 9), f, "element", &state.element_ids);
}

void parse_ctria3(const CardFields& f, DeckState& state) {
  insert_unique(state.deck.triangles, shell_card<3>(f, 8), f, "element", &state.element_ids);
}

void parse_conm2(const CardFields& f, DeckState& state) {
  MassCard m;
  m.id = f.id(2, "EID");
  m.grid = f.id(3, "G");
  m.system = f.integer_or(4, "CID", 0);
  if (m.system < -1) f.fail(4, "CID", "expected -1, 0 or a coordinate system id");
  m.mass = f.real_or(5, "M", 0.0);
  if (!(m.mass >= 0.0)) f.fail(5, "M", "expected a mass >= 0");
  m.offset = {f.real_or(6, "X1", 0.0), f.real_or(7, "X2", 0.0), f.real_or(8, "X3", 0.0)};
  const double i11 = f.real_or(12, "I11", 0.0), i21 = f.real_or(13, "I21", 0.0),
               i22 = f.real_or(14, "I22", 0.0), i31 = f.real_or(15, "I31", 0.0),
               i32 = f.real_or(16, "I32", 0.0), i33 = f.real_or(17, "I33", 0.0);
  // NASTRAN's products of inertia enter with a minus sign (CONM2 mass matrix).
  m.inertia << i11, -i21, -i31, -i21, i22, -i32, -i31, -i32, i33;
  m.where = f.card().where();
  m.grid_where = f.where(3);
  m.system_where = f.where(4);
  insert_unique(state.deck.masses, std::move(m), f, "element", &state.element_ids);
}

void parse_rbe2(const CardFields& f, DeckState& state) {
  RigidElementCard r;
  r.id = f.id(2, "EID");
  r.independent = f.id(3, "GN");
  r.components = components(f, 4, "CM");
  if (r.components.empty()) f.fail(4, "CM", "expected component digits 1-6, got blank");
  r.where = f.card().where();
  r.independent_where = f.where(3);
  // GMi, then an optional ALPHA (a real: thermal expansion, no effect on stiffness or mass).
  for (int field : data_fields(f, 5)) {
    if (f.blank(field)) continue;
    if (!f.is_integer(field)) {
      f.real(field, "ALPHA");  // a bad field is still an error
      break;
    }
    r.dependent.push_back(f.id(field, "GM"));
    r.dependent_where.push_back(f.where(field));
  }
  if (r.dependent.empty()) f.fail(5, "GM1", "expected at least one dependent grid, got none");
  insert_unique(state.deck.rigid_elements, std::move(r), f, "element", &state.element_ids);
}

void parse_rbe3(const CardFields& f, DeckState& state) {
  InterpolationElementCard r;
  r.id = f.id(2, "EID");
  if (!f.blank(3)) f.fail(3, "blank", fmt::format("expected a blank field 3, got '{}'", f.text(3)));
  r.reference = f.id(4, "REFGRID");
  r.reference_components = components(f, 5, "REFC");
  if (r.reference_components.empty()) f.fail(5, "REFC", "expected component digits 1-6, got blank");
  r.where = f.card().where();
  r.reference_where = f.where(4);
  // WTi Ci Gi,j ... groups, then optional UM (not supported) and ALPHA (thermal only).
  const std::vector<int> fields = data_fields(f, 6);
  for (std::size_t k = 0; k < fields.size(); ++k) {
    const int field = fields[k];
    if (f.blank(field)) continue;
    const std::string& text = f.text(field);
    if (text == "ALPHA") break;
    if (text == "UM") {
      f.fail(field, "UM", "expected no UM list (moving the dependent DOFs off the reference grid "
                          "is not supported)");
    }
    if (!f.is_integer(field)) {
      InterpolationElementCard::Group group;
      group.weight = f.real(field, "WT");
      if (!(group.weight > 0.0)) f.fail(field, "WT", fmt::format("expected a weight > 0, got {}", group.weight));
      if (k + 1 >= fields.size()) f.fail(field, "C", "expected components after the weight, got none");
      group.components = components(f, fields[k + 1], "C");
      if (group.components.empty()) f.fail(fields[k + 1], "C", "expected component digits 1-6, got blank");
      ++k;
      r.groups.push_back(std::move(group));
      continue;
    }
    if (r.groups.empty()) f.fail(field, "WT1", fmt::format("expected a weight (a real), got '{}'", text));
    r.groups.back().grids.push_back(f.id(field, "G"));
    r.groups.back().grid_where.push_back(f.where(field));
  }
  if (r.groups.empty()) f.fail(6, "WT1", "expected at least one weight, components and grids");
  for (const auto& group : r.groups) {
    if (group.grids.empty()) f.fail_card("expected grids after each weight and components, got none");
  }
  insert_unique(state.deck.interpolation_elements, std::move(r), f, "element", &state.element_ids);
}

// CELAS1, CELAS2, CMASS1, CMASS2: EID PID|value G1 C1 G2 C2.
void parse_scalar(const CardFields& f, DeckState& state) {
  ScalarElementCard e;
  e.card = f.card().name;
  e.id = f.id(2, "EID");
  const bool by_property = e.card.back() == '1';
  const bool spring = e.card.starts_with("CELAS");
  if (by_property) {
    e.property = f.blank(3) ? e.id : f.id(3, "PID");
  } else {
    e.value = f.real(3, spring ? "K" : "M");
    if (!spring && !(e.value >= 0.0)) f.fail(3, "M", "expected a mass >= 0");
  }
  e.where = f.card().where();
  e.property_where = f.where(3);
  for (int end = 0; end < 2; ++end) {
    const int g = 4 + 2 * end;
    const char* gname = end == 0 ? "G1" : "G2";
    const char* cname = end == 0 ? "C1" : "C2";
    ScalarEnd& out = e.ends[static_cast<std::size_t>(end)];
    out.grid = f.integer_or(g, gname, 0);
    out.where = f.where(g);
    if (out.grid < 0) f.fail(g, gname, "expected a grid id > 0 or blank (ground)");
    out.component = f.integer_or(g + 1, cname, 0);
    if (out.grid == 0 && out.component != 0) f.fail(g + 1, cname, "expected blank for a grounded end");
    if (out.grid != 0 && (out.component < 1 || out.component > 6)) {
      f.fail(g + 1, cname, fmt::format("expected a component 1-6 (scalar points are not supported), got '{}'",
                                       f.text(g + 1)));
    }
  }
  if (e.ends[0].grid == 0 && e.ends[1].grid == 0) f.fail(4, "G1", "expected at least one grid, got none");
  // CELAS2's GE and S (damping, stress) do not change stiffness or mass.
  insert_unique(state.deck.scalar_elements, std::move(e), f, "element", &state.element_ids);
}

void parse_cbush(const CardFields& f, DeckState& state) {
  BushCard b;
  b.id = f.id(2, "EID");
  b.property = f.blank(3) ? b.id : f.id(3, "PID");
  b.grids = {f.id(4, "GA"), f.integer_or(5, "GB", 0)};
  if (b.grids[1] < 0) f.fail(5, "GB", "expected a grid id or blank (grounded)");
  b.where = f.card().where();
  b.property_where = f.where(3);
  b.grid_where = {f.where(4), f.where(5)};
  b.system_where = f.where(9);
  for (int field = 6; field <= 8; ++field) {
    if (!f.blank(field)) {
      f.fail(field, field == 6 ? "GO/X1" : field == 7 ? "X2" : "X3",
             "expected blank (element axes from an orientation vector are not supported; give CID)");
    }
  }
  if (f.blank(9)) f.fail(9, "CID", "expected a coordinate system id (0: basic) for the element axes, got blank");
  b.system = f.integer(9, "CID");
  if (b.system < 0) f.fail(9, "CID", "expected a coordinate system id >= 0");
  demand_zero(f, 12, "S", "a spring location other than GA is");
  if (!f.blank(13)) f.fail(13, "OCID", "expected blank (offsets are not supported)");
  for (int field = 14; field <= 16; ++field) demand_zero(f, field, "S1-S3", "an offset is");
  insert_unique(state.deck.bushes, std::move(b), f, "element", &state.element_ids);
}

void parse_conm1(const CardFields& f, DeckState& state) {
  GeneralMassCard m;
  m.id = f.id(2, "EID");
  m.grid = f.id(3, "G");
  m.system = f.integer_or(4, "CID", 0);
  if (m.system < 0) f.fail(4, "CID", "expected a coordinate system id >= 0");
  // Lower triangle row by row: M11, M21, M22, M31, ... from field 5 on.
  int field = 5;
  for (int i = 0; i < 6; ++i) {
    for (int j = 0; j <= i; ++j, ++field) {
      if (field % 10 == 0) field += 2;
      const std::string name = fmt::format("M{}{}", i + 1, j + 1);
      m.mass(i, j) = m.mass(j, i) = f.real_or(field, name.c_str(), 0.0);
    }
  }
  m.where = f.card().where();
  m.grid_where = f.where(3);
  m.system_where = f.where(4);
  insert_unique(state.deck.general_masses, std::move(m), f, "element", &state.element_ids);
}

void parse_crod(const CardFields& f, DeckState& state) {
  RodCard r;
  r.card = "CROD";
  r.id = f.id(2, "EID");
  r.property = f.blank(3) ? r.id : f.id(3, "PID");
  r.grids = {f.id(4, "G1"), f.id(5, "G2")};
  r.where = f.card().where();
  r.property_where = f.where(3);
  r.grid_where = {f.where(4), f.where(5)};
  insert_unique(state.deck.rods, std::move(r), f, "element", &state.element_ids);
}

void parse_conrod(const CardFields& f, DeckState& state) {
  RodCard r;
  r.card = "CONROD";
  r.id = f.id(2, "EID");
  r.grids = {f.id(3, "G1"), f.id(4, "G2")};
  r.material = f.id(5, "MID");
  rod_section(f, 6, r.area, r.torsion_constant, r.nonstructural_mass);
  r.where = f.card().where();
  r.grid_where = {f.where(3), f.where(4)};
  r.material_where = f.where(5);
  insert_unique(state.deck.rods, std::move(r), f, "element", &state.element_ids);
}

}  // namespace limber::bulkdata
