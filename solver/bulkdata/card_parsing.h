// The shared pieces of the bulk-data card parsers: the deck being built, with the id
// registries that span card kinds, and the field checks every parser uses. parse_deck
// (deck_parser.h) dispatches each card to property_cards.h, element_cards.h or its own GRID,
// coordinate-system, SPC and SET parsers. Every check throws InputError at the field
// (card_fields.h).
#pragma once

#include <fmt/format.h>

#include <map>
#include <string>
#include <vector>

#include "bulkdata/card_fields.h"
#include "bulkdata/deck.h"

namespace limber::bulkdata {

// The deck being built, and the ids that must be unique across card kinds.
struct DeckState {
  Deck deck;
  std::map<int, SourceLocation> property_ids;  // every property card (PBAR ... PROD)
  std::map<int, SourceLocation> element_ids;   // every element card (CBAR ... RBE3)
};

// Fails unless the field is blank or the real zero.
void demand_zero(const CardFields& f, int field, const char* name, const char* what);

// A real > 0.
double positive(const CardFields& f, int field, const char* name);

// DOF component digits 1-6, each at most once ("" when blank).
std::string components(const CardFields& f, int field, const char* name);

// Ids from `first` to the card's last field, with "A THRU B" ranges; blanks are skipped.
std::vector<IdRange> id_list(const CardFields& f, int first, const char* name);

// The data fields of a card from `first` on (continuation markers skipped).
std::vector<int> data_fields(const CardFields& f, int first);

// A, J, (C: stress only), NSM from `first` on.
void rod_section(const CardFields& f, int first, double& area, double& torsion, double& nsm);

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

}  // namespace limber::bulkdata
