// NASTRAN bulk-data cards as text: the tokenizer of a deck (docs/bulk-data.md, "Card format").
//
// Reads a deck file into cards, each a name and its data fields with their places in the file:
//  - small field: 8-column fields, name in columns 1-8, 8 data fields in 9-72;
//  - large field: a name ending in '*', 4 data fields of 16 columns in 9-72;
//  - free field: fields separated by commas (a line holding a comma), 8 data fields a line
//    (4 for a large-field name);
//  - continuation lines: the first field starts with '+' or '*' (explicit; '*' makes the line
//    large field) or is blank (implicit); each line's data fields are padded to a full line
//    (8 small or 4 large fields), so a continuation always starts a new block of fields. A
//    continuation whose marker (field 1, its leading '+' or '*' aside) matches the marker in
//    columns 73-80 (field 10) of an earlier card's last line continues that card, wherever it
//    is in the deck (old sorted decks); one without a match continues the card above it;
//  - '$' starts a comment, to the end of the line; tabs move to the next multiple of 8 columns;
//  - INCLUDE 'path' (path relative to the including file; quotes optional) reads another file
//    of bulk data in place; an include cycle is an error;
//  - a main file holding BEGIN BULK is read after that line (executive and case control
//    skipped); without it, the whole file is bulk data; ENDDATA ends the deck;
//  - case-control "SET n = 1, 5 THRU 9, ..." lines (continued by a trailing comma) become
//    cards named SET (fields: n, then the members, THRU kept), placed before the bulk data;
//    sets of other forms (ALL, EXCEPT, BY, reals) are skipped.
// Field text is trimmed and upper-cased; names lose their '*'.
//
// Errors are InputError at file:line:column (an unreadable file at the INCLUDE that names it).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "core/error.h"

namespace limber::bulkdata {

// One data field: its text and where it starts.
struct Field {
  std::string text;  // trimmed, upper case; empty when blank
  int line = 0;      // 1-based
  int column = 0;    // 1-based column of the field's first character
};

struct Card {
  std::string name;                        // upper case, without '*', e.g. "GRID"
  std::shared_ptr<const std::string> file;  // the file it is in (path as opened)
  int line = 0;                            // line of its first line
  std::vector<Field> fields;               // data fields: fields[0] is NASTRAN field 2

  SourceLocation where() const { return {*file, line, 1}; }
  SourceLocation where(const Field& field) const { return {*file, field.line, field.column}; }
};

// Reads the deck at `path` and every file it includes. `where` is the place that names the
// deck (the case file entry), used when the file cannot be opened.
std::vector<Card> read_cards(const std::string& path, const SourceLocation& where = {});

// Same from text (tests, fuzzing); `file` names the text in messages and is the folder base of
// INCLUDE paths.
std::vector<Card> read_cards_text(const std::string& text, const std::string& file);

}  // namespace limber::bulkdata
