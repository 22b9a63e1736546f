#include "bulkdata/deck_parser.h"

#include <fmt/format.h>

#include <set>
#include <unordered_map>

#include "bulkdata/card_parsing.h"
#include "bulkdata/element_cards.h"
#include "bulkdata/property_cards.h"

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

void parse_grid(const CardFields& f, DeckState& state) {
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
  insert_unique(state.deck.grids, std::move(g), f, "GRID");
}

void parse_cord2(const CardFields& f, DeckState& state) {
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
  insert_unique(state.deck.coordinate_systems, std::move(c), f, "coordinate system");
}

void parse_spc1(const CardFields& f, DeckState& state) {
  const int set = f.id(2, "SID");
  const std::string dofs = components(f, 3, "C");
  if (dofs.empty()) f.fail(3, "C", "expected component digits, got blank");
  for (const IdRange& grids : id_list(f, 4, "G")) {
    state.deck.spcs.push_back({set, grids, dofs, f.card().where()});
  }
}

void parse_spc(const CardFields& f, DeckState& state) {
  const int set = f.id(2, "SID");
  for (int first : {3, 6}) {
    if (first == 6 && f.blank(6)) break;
    const int grid = f.id(first, "G");
    const std::string dofs = components(f, first + 1, "C");
    demand_zero(f, first + 2, "D", "an enforced displacement is");
    state.deck.spcs.push_back({set, {grid, grid}, dofs, f.card().where()});
  }
}

void parse_spcadd(const CardFields& f, DeckState& state) {
  const int set = f.id(2, "SID");
  std::vector<IdRange>& sets = state.deck.spc_sets_added[set];
  for (const IdRange& range : id_list(f, 3, "S")) sets.push_back(range);
}

void parse_set1(const CardFields& f, DeckState& state) {
  const int id = f.id(2, "SID");
  if (state.deck.sets.contains(id)) {
    f.fail(2, "SID", fmt::format("expected a unique set id (SET1 cards and case-control SET "
                                 "lines both name node sets set<id>), got {} again", id));
  }
  state.deck.sets.emplace(id, id_list(f, 3, "ID"));
}

void parse_param(const CardFields& f, DeckState& state) {
  if (f.text(2) == "WTMASS") {
    state.deck.mass_factor = f.real(3, "V1");
    if (!(state.deck.mass_factor > 0.0)) f.fail(3, "V1", "expected WTMASS > 0");
    return;
  }
  tally(state.deck.ignored, f.card());
}

using Handler = void (*)(const CardFields&, DeckState&);
// Each supported card to its parser; the rest are tallied as ignored or unsupported.
const std::unordered_map<std::string, Handler> kHandlers = {
    {"GRID", parse_grid},     {"CORD2R", parse_cord2},  {"CORD2C", parse_cord2},
    {"CORD2S", parse_cord2},  {"MAT1", parse_mat1},     {"PBAR", parse_pbar},
    {"PBARL", parse_pbarl},   {"PBEAM", parse_pbeam},   {"PSHELL", parse_pshell},
    {"CBAR", parse_cbar},     {"CBEAM", parse_cbar},    {"CQUAD4", parse_cquad4},
    {"CTRIA3", parse_ctria3},
    {"CONM2", parse_conm2},   {"SPC", parse_spc},       {"SPC1", parse_spc1},
    {"SPCADD", parse_spcadd}, {"SET1", parse_set1},     {"PARAM", parse_param},
    {"RBE2", parse_rbe2},     {"RBE3", parse_rbe3},     {"CELAS1", parse_scalar},
    {"CELAS2", parse_scalar}, {"CMASS1", parse_scalar}, {"CMASS2", parse_scalar},
    {"PELAS", parse_pelas},   {"PMASS", parse_pmass},   {"CBUSH", parse_cbush},
    {"PBUSH", parse_pbush},   {"CONM1", parse_conm1},   {"CROD", parse_crod},
    {"CONROD", parse_conrod}, {"PROD", parse_prod},     {"SET", parse_set1}};

void parse_card(const Card& card, DeckState& state) {
  const CardFields f(card);
  if (auto found = kHandlers.find(card.name); found != kHandlers.end()) {
    found->second(f, state);
  } else if (kIgnoredCards.contains(card.name)) {
    tally(state.deck.ignored, card);
  } else {
    tally(state.deck.unsupported, card);
  }
}

}  // namespace

Deck parse_deck(const std::vector<Card>& cards, const std::string& file) {
  DeckState state;
  state.deck.file = file;
  for (const Card& card : cards) parse_card(card, state);
  return std::move(state.deck);
}

Deck read_deck(const std::string& path, const SourceLocation& where) {
  return parse_deck(read_cards(path, where), path);
}

}  // namespace limber::bulkdata
