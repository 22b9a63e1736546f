// The element cards of a bulk-data deck (CBAR, CBEAM, CQUAD4, CTRIA3, CONM1, CONM2, CELAS1/2,
// CMASS1/2, CBUSH, CROD, CONROD, RBE2, RBE3): each checked field by field into the deck, its id
// unique among all elements (docs/bulk-data.md).
#pragma once

#include "bulkdata/card_parsing.h"

namespace limber::bulkdata {

void parse_cbar(const CardFields& f, DeckState& state);
void parse_cquad4(const CardFields& f, DeckState& state);
void parse_ctria3(const CardFields& f, DeckState& state);
void parse_conm2(const CardFields& f, DeckState& state);
void parse_rbe2(const CardFields& f, DeckState& state);
void parse_rbe3(const CardFields& f, DeckState& state);
void parse_scalar(const CardFields& f, DeckState& state);
void parse_cbush(const CardFields& f, DeckState& state);
void parse_conm1(const CardFields& f, DeckState& state);
void parse_crod(const CardFields& f, DeckState& state);
void parse_conrod(const CardFields& f, DeckState& state);

}  // namespace limber::bulkdata
