#include "bulkdata/deck_parser.h"

#include <fmt/format.h>

#include <cmath>
#include <functional>
#include <set>
#include <unordered_map>

#include "bulkdata/card_fields.h"
#include "bulkdata/pbarl_section.h"

namespace limber::bulkdata {

namespace {

constexpr std::size_t kTallyPlaces = 5;

// Cards that do not change the structure's stiffness or mass.
const std::set<std::string> kIgnoredCards = {
    "ASET",  "ASET1",  "BSET",   "BSET1",  "CSET",   "CSET1",  "DAREA",  "DELAY",  "DLOAD",
    "DPHASE", "EIGB",  "EIGC",   "EIGR",   "EIGRL",  "FORCE",  "FORCE1", "FORCE2", "FREQ",
    "FREQ1", "FREQ2",  "GRAV",   "LOAD",   "MAT4",   "MAT5",   "MOMENT", "MOMENT1", "MOMENT2",
    "NLPARM", "PARAM", "PLOAD",  "PLOAD1", "PLOAD2", "PLOAD4", "PLOTEL", "QSET",   "QSET1",
    "RFORCE", "RLOAD1", "RLOAD2", "SPCD",  "SUPORT", "TABDMP1", "TABLED1", "TABLED2", "TABLED3",
    "TABLED4", "TEMP", "TEMPD",  "TLOAD1", "TLOAD2", "TSTEP"};

void tally(std::map<std::string, CardTally>& tallies, const Card& card) {
  CardTally& entry = tallies[card.name];
  ++entry.count;
  if (entry.first.size() < kTallyPlaces) entry.first.push_back(card.where());
}

// Fails unless the field is blank or the real zero.
void demand_zero(const CardFields& f, int field, const char* name, const char* what) {
  if (f.blank(field)) return;
  const std::optional<int> as_integer = parse_integer(f.text(field));
  const double value = as_integer ? *as_integer : f.real(field, name);
  if (value != 0.0) {
    f.fail(field, name, fmt::format("expected blank or 0.0 ({} not supported), got '{}'", what,
                                    f.text(field)));
  }
}

double positive(const CardFields& f, int field, const char* name) {
  const double value = f.real(field, name);
  if (!(value > 0.0)) f.fail(field, name, fmt::format("expected a value > 0, got {}", value));
  return value;
}

// DOF component digits 1-6, each at most once ("" when blank).
std::string components(const CardFields& f, int field, const char* name) {
  const std::string& text = f.text(field);
  std::set<char> seen;
  for (char c : text) {
    if (c < '1' || c > '6' || !seen.insert(c).second) {
      f.fail(field, name,
             fmt::format("expected component digits 1-6, each once (e.g. 123456), got '{}'", text));
    }
  }
  return text;
}

// Ids from `first` to the card's last field, with "A THRU B" ranges; blanks are skipped.
std::vector<IdRange> id_list(const CardFields& f, int first, const char* name) {
  std::vector<IdRange> ids;
  const int last = f.last_field();
  const auto skipped = [&](int field) { return field % 10 == 0 || field % 10 == 1 || f.blank(field); };
  for (int field = first; field <= last; ++field) {
    if (skipped(field)) continue;  // continuation markers, blanks
    if (f.text(field) == "THRU") {
      int next = field + 1;
      while (next <= last && skipped(next)) ++next;
      if (ids.empty() || ids.back().first != ids.back().last || next > last) {
        f.fail(field, name, "expected 'id THRU id', got THRU without an id on both sides");
      }
      const int to = f.id(next, name);
      if (to < ids.back().first) {
        f.fail(next, name, fmt::format("expected an end id >= {}, got {}", ids.back().first, to));
      }
      ids.back().last = to;
      field = next;
      continue;
    }
    const int id = f.id(field, name);
    ids.push_back({id, id});
  }
  if (ids.empty()) f.fail(first, name, "expected at least one id, got none");
  return ids;
}

// Inserts a card under its id, or fails at the id field naming the first definition.
template <class T>
void insert_unique(std::map<int, T>& map, T value, const CardFields& f, const char* what,
                   std::map<int, SourceLocation>* shared = nullptr) {
  const int id = value.id;
  const SourceLocation* earlier = nullptr;
  if (auto found = map.find(id); found != map.end()) earlier = &found->second.where;
  if (shared) {
    if (auto found = shared->find(id); found != shared->end()) earlier = &found->second;
  }
  if (earlier) {
    f.fail(2, "ID", fmt::format("expected a unique {} id, got {} again (first at {})", what, id,
                                earlier->to_string()));
  }
  if (shared) shared->emplace(id, value.where);
  map.emplace(id, std::move(value));
}

class Parser {
 public:
  explicit Parser(const std::string& file) { deck_.file = file; }

  Deck take() && { return std::move(deck_); }

  void parse(const Card& card) {
    const CardFields f(card);
    using Handler = void (Parser::*)(const CardFields&);
    static const std::unordered_map<std::string, Handler> handlers = {
        {"GRID", &Parser::grid},     {"CORD2R", &Parser::cord2},  {"CORD2C", &Parser::cord2},
        {"CORD2S", &Parser::cord2},  {"MAT1", &Parser::mat1},     {"PBAR", &Parser::pbar},
        {"PBARL", &Parser::pbarl},   {"PBEAM", &Parser::pbeam},   {"PSHELL", &Parser::pshell},
        {"CBAR", &Parser::cbar},     {"CBEAM", &Parser::cbar},    {"CQUAD4", &Parser::cquad4},
        {"CTRIA3", &Parser::ctria3},
        {"CONM2", &Parser::conm2},   {"SPC", &Parser::spc},       {"SPC1", &Parser::spc1},
        {"SPCADD", &Parser::spcadd}, {"SET1", &Parser::set1},     {"PARAM", &Parser::param},
        {"RBE2", &Parser::rbe2},     {"RBE3", &Parser::rbe3},     {"CELAS1", &Parser::scalar},
        {"CELAS2", &Parser::scalar}, {"CMASS1", &Parser::scalar}, {"CMASS2", &Parser::scalar},
        {"PELAS", &Parser::pelas},   {"PMASS", &Parser::pmass},   {"CBUSH", &Parser::cbush},
        {"PBUSH", &Parser::pbush},   {"CONM1", &Parser::conm1},   {"CROD", &Parser::crod},
        {"CONROD", &Parser::conrod}, {"PROD", &Parser::prod},     {"SET", &Parser::set1}};
    if (auto found = handlers.find(card.name); found != handlers.end()) {
      (this->*found->second)(f);
    } else if (kIgnoredCards.contains(card.name)) {
      tally(deck_.ignored, card);
    } else {
      tally(deck_.unsupported, card);
    }
  }

 private:
  Deck deck_;
  std::map<int, SourceLocation> property_ids_;
  std::map<int, SourceLocation> element_ids_;

  void grid(const CardFields& f) {
    GridCard g;
    g.id = f.id(2, "ID");
    g.position_system = f.integer_or(3, "CP", 0);
    if (g.position_system < 0) f.fail(3, "CP", "expected a coordinate system id >= 0");
    g.position = {f.real_or(4, "X1", 0.0), f.real_or(5, "X2", 0.0), f.real_or(6, "X3", 0.0)};
    g.displacement_system = f.integer_or(7, "CD", 0);
    if (g.displacement_system < 0) {
      f.fail(7, "CD", "expected a coordinate system id >= 0 (-1, a fluid point, is not supported)");
    }
    g.permanent_spc = components(f, 8, "PS");
    if (f.integer_or(9, "SEID", 0) != 0) f.fail(9, "SEID", "expected 0 (superelements are not supported)");
    g.where = f.card().where();
    g.cp_where = f.where(3);
    g.cd_where = f.where(7);
    insert_unique(deck_.grids, std::move(g), f, "GRID");
  }

  void cord2(const CardFields& f) {
    CoordinateSystemCard c;
    const std::string& name = f.card().name;
    c.type = name == "CORD2R"   ? CoordinateSystemCard::Type::kRectangular
             : name == "CORD2C" ? CoordinateSystemCard::Type::kCylindrical
                                : CoordinateSystemCard::Type::kSpherical;
    c.id = f.id(2, "CID");
    c.reference = f.integer_or(3, "RID", 0);
    if (c.reference < 0) f.fail(3, "RID", "expected a coordinate system id >= 0");
    c.a = {f.real_or(4, "A1", 0.0), f.real_or(5, "A2", 0.0), f.real_or(6, "A3", 0.0)};
    c.b = {f.real_or(7, "B1", 0.0), f.real_or(8, "B2", 0.0), f.real_or(9, "B3", 0.0)};
    c.c = {f.real_or(12, "C1", 0.0), f.real_or(13, "C2", 0.0), f.real_or(14, "C3", 0.0)};
    c.where = f.card().where();
    c.reference_where = f.where(3);
    insert_unique(deck_.coordinate_systems, std::move(c), f, "coordinate system");
  }

  void mat1(const CardFields& f) {
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
    insert_unique(deck_.materials, std::move(m), f, "MAT1");
  }

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

  void pbar(const CardFields& f) {
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
    insert_unique(deck_.beam_properties, std::move(p), f, "property", &property_ids_);
  }

  void pbarl(const CardFields& f) {
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
    insert_unique(deck_.beam_properties, std::move(p), f, "property", &property_ids_);
  }

  // PBEAM with a constant section: line 1 (A end), optional stress points, optional stations
  // that repeat the A end, and the optional K1.../M1... lines.
  void pbeam(const CardFields& f) {
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
    insert_unique(deck_.beam_properties, std::move(p), f, "property", &property_ids_);
  }

  void pshell(const CardFields& f) {
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
    insert_unique(deck_.shell_properties, std::move(p), f, "property", &property_ids_);
  }

  void cbar(const CardFields& f) {
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
    insert_unique(deck_.beams, std::move(b), f, "element", &element_ids_);
  }

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

  void cquad4(const CardFields& f) {
    insert_unique(deck_.quads, shell_card<4>(f, 9), f, "element", &element_ids_);
  }

  void ctria3(const CardFields& f) {
    insert_unique(deck_.triangles, shell_card<3>(f, 8), f, "element", &element_ids_);
  }

  void conm2(const CardFields& f) {
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
    insert_unique(deck_.masses, std::move(m), f, "element", &element_ids_);
  }

  void spc1(const CardFields& f) {
    const int set = f.id(2, "SID");
    const std::string dofs = components(f, 3, "C");
    if (dofs.empty()) f.fail(3, "C", "expected component digits, got blank");
    for (const IdRange& grids : id_list(f, 4, "G")) {
      deck_.spcs.push_back({set, grids, dofs, f.card().where()});
    }
  }

  void spc(const CardFields& f) {
    const int set = f.id(2, "SID");
    for (int first : {3, 6}) {
      if (first == 6 && f.blank(6)) break;
      const int grid = f.id(first, "G");
      const std::string dofs = components(f, first + 1, "C");
      demand_zero(f, first + 2, "D", "an enforced displacement is");
      deck_.spcs.push_back({set, {grid, grid}, dofs, f.card().where()});
    }
  }

  void spcadd(const CardFields& f) {
    const int set = f.id(2, "SID");
    std::vector<IdRange>& sets = deck_.spc_sets_added[set];
    for (const IdRange& range : id_list(f, 3, "S")) sets.push_back(range);
  }

  void set1(const CardFields& f) {
    const int id = f.id(2, "SID");
    if (deck_.sets.contains(id)) {
      f.fail(2, "SID", fmt::format("expected a unique set id (SET1 cards and case-control SET "
                                   "lines both name node sets set<id>), got {} again", id));
    }
    deck_.sets.emplace(id, id_list(f, 3, "ID"));
  }

  // The data fields of a card from `first` on (continuation markers skipped).
  static std::vector<int> data_fields(const CardFields& f, int first) {
    std::vector<int> fields;
    for (int field = first; field <= f.last_field(); ++field) {
      if (field % 10 == 0 || field % 10 == 1) continue;
      fields.push_back(field);
    }
    return fields;
  }

  void rbe2(const CardFields& f) {
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
    insert_unique(deck_.rigid_elements, std::move(r), f, "element", &element_ids_);
  }

  void rbe3(const CardFields& f) {
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
    insert_unique(deck_.interpolation_elements, std::move(r), f, "element", &element_ids_);
  }

  // CELAS1, CELAS2, CMASS1, CMASS2: EID PID|value G1 C1 G2 C2.
  void scalar(const CardFields& f) {
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
    insert_unique(deck_.scalar_elements, std::move(e), f, "element", &element_ids_);
  }

  // PELAS: up to two (PID, K, GE, S); PMASS: up to four (PID, M).
  void scalar_properties(const CardFields& f, int stride, int count, const char* value_name) {
    for (int k = 0; k < count; ++k) {
      const int field = 2 + stride * k;
      if (k > 0 && f.blank(field)) continue;
      ScalarPropertyCard p;
      p.card = f.card().name;
      p.id = f.id(field, "PID");
      p.value = f.real(field + 1, value_name);
      if (p.card == "PMASS" && !(p.value >= 0.0)) f.fail(field + 1, value_name, "expected a mass >= 0");
      p.where = f.card().where();
      if (property_ids_.contains(p.id)) {
        f.fail(field, "PID", fmt::format("expected a unique property id, got {} again (first at {})",
                                         p.id, property_ids_.at(p.id).to_string()));
      }
      property_ids_.emplace(p.id, p.where);
      deck_.scalar_properties.emplace(p.id, std::move(p));
    }
  }
  void pelas(const CardFields& f) { scalar_properties(f, 4, 2, "K"); }
  void pmass(const CardFields& f) { scalar_properties(f, 2, 4, "M"); }

  void cbush(const CardFields& f) {
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
    insert_unique(deck_.bushes, std::move(b), f, "element", &element_ids_);
  }

  void pbush(const CardFields& f) {
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
        deck_.parse_notices.push_back(fmt::format(
            "PBUSH {} ({}:{}): {} (damping) left out: damping is modal, in the case file", p.id,
            p.where.file, p.where.line, word));
      } else if (word != "RCV") {
        f.fail(key, "keyword", fmt::format("expected K, B, GE or RCV (other PBUSH lines are not "
                                           "supported), got '{}'", word));
      }
    }
    if (!stiffness) f.fail(3, "K", "expected a K line with K1-K6");
    insert_unique(deck_.bush_properties, std::move(p), f, "property", &property_ids_);
  }

  void conm1(const CardFields& f) {
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
    insert_unique(deck_.general_masses, std::move(m), f, "element", &element_ids_);
  }

  void crod(const CardFields& f) {
    RodCard r;
    r.card = "CROD";
    r.id = f.id(2, "EID");
    r.property = f.blank(3) ? r.id : f.id(3, "PID");
    r.grids = {f.id(4, "G1"), f.id(5, "G2")};
    r.where = f.card().where();
    r.property_where = f.where(3);
    r.grid_where = {f.where(4), f.where(5)};
    insert_unique(deck_.rods, std::move(r), f, "element", &element_ids_);
  }

  // A, J, (C: stress only), NSM from `first` on.
  static void rod_section(const CardFields& f, int first, double& area, double& torsion, double& nsm) {
    area = positive(f, first, "A");
    torsion = f.real_or(first + 1, "J", 0.0);
    if (torsion < 0.0) f.fail(first + 1, "J", "expected a torsion constant >= 0");
    nsm = f.real_or(first + 3, "NSM", 0.0);
    if (!(nsm >= 0.0)) f.fail(first + 3, "NSM", "expected a value >= 0");
  }

  void conrod(const CardFields& f) {
    RodCard r;
    r.card = "CONROD";
    r.id = f.id(2, "EID");
    r.grids = {f.id(3, "G1"), f.id(4, "G2")};
    r.material = f.id(5, "MID");
    rod_section(f, 6, r.area, r.torsion_constant, r.nonstructural_mass);
    r.where = f.card().where();
    r.grid_where = {f.where(3), f.where(4)};
    r.material_where = f.where(5);
    insert_unique(deck_.rods, std::move(r), f, "element", &element_ids_);
  }

  void prod(const CardFields& f) {
    RodPropertyCard p;
    p.id = f.id(2, "PID");
    p.material = f.id(3, "MID");
    rod_section(f, 4, p.area, p.torsion_constant, p.nonstructural_mass);
    p.where = f.card().where();
    p.material_where = f.where(3);
    insert_unique(deck_.rod_properties, std::move(p), f, "property", &property_ids_);
  }

  void param(const CardFields& f) {
    if (f.text(2) == "WTMASS") {
      deck_.mass_factor = f.real(3, "V1");
      if (!(deck_.mass_factor > 0.0)) f.fail(3, "V1", "expected WTMASS > 0");
      return;
    }
    tally(deck_.ignored, f.card());
  }
};

}  // namespace

Deck parse_deck(const std::vector<Card>& cards, const std::string& file) {
  Parser parser(file);
  for (const Card& card : cards) parser.parse(card);
  return std::move(parser).take();
}

Deck read_deck(const std::string& path, const SourceLocation& where) {
  return parse_deck(read_cards(path, where), path);
}

}  // namespace limber::bulkdata
