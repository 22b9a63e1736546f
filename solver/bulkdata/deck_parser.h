// Cards (card_reader.h) -> Deck (deck.h): each supported card parsed and checked field by
// field (docs/bulk-data.md, "Cards read"); other cards tallied as ignored (loads, solution
// requests, output) or unsupported (anything else, assumed to change the structure).
//
// Throws InputError at the field for: a bad field (type, range, a feature limber does not
// model such as beam offsets, pin flags, shell offsets, tapered PBEAM, coupled I12, RBE3's
// UM, CBUSH orientation vectors and offsets, scalar points), duplicate ids (grids; coordinate
// systems; materials; properties incl. PELAS, PMASS, PBUSH, PROD; elements incl. CONM1,
// CONM2, CELAS, CMASS, CBUSH, CROD, RBE2, RBE3; SET1 and case-control SET ids),
// and the MAT1 rule (two of E, G, nu; all three only when consistent within 1 %).
#pragma once

#include <string>
#include <vector>

#include "bulkdata/card_reader.h"
#include "bulkdata/deck.h"

namespace limber::bulkdata {

Deck parse_deck(const std::vector<Card>& cards, const std::string& file);

// read_cards + parse_deck.
Deck read_deck(const std::string& path, const SourceLocation& where = {});

}  // namespace limber::bulkdata
