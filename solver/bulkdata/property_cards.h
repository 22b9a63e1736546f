// The property and material cards of a bulk-data deck (MAT1, PBAR, PBARL, PBEAM, PSHELL,
// PELAS, PMASS, PBUSH, PROD): each checked field by field into the deck (docs/bulk-data.md).
#pragma once

#include "bulkdata/card_parsing.h"

namespace limber::bulkdata {

void parse_mat1(const CardFields& f, DeckState& state);
void parse_pbar(const CardFields& f, DeckState& state);
void parse_pbarl(const CardFields& f, DeckState& state);
void parse_pbeam(const CardFields& f, DeckState& state);
void parse_pshell(const CardFields& f, DeckState& state);
void parse_pelas(const CardFields& f, DeckState& state);
void parse_pmass(const CardFields& f, DeckState& state);
void parse_pbush(const CardFields& f, DeckState& state);
void parse_prod(const CardFields& f, DeckState& state);

}  // namespace limber::bulkdata
