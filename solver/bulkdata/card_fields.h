// Typed access to the data fields of one bulk-data card (card_reader.h), NASTRAN rules:
//  - an integer field holds digits with an optional sign ("12", "-1");
//  - a real field must hold a decimal point ("7.0E10", "7.+10", "70.D9", ".5", "-1.-3"): the
//    exponent may be written with E or D, or as a bare signed number after the mantissa;
//    "7" in a real field is an error, as in NASTRAN (where it can mean a grid id instead);
//  - a blank field takes the card's default, or is an error when the field is required.
// Fields are numbered as in the NASTRAN manuals, from the card's first line: field 1 is the
// name, 2-9 the data of the first line, 10 its continuation marker, and 12-19 the data of the
// first continuation (field 11 and 20 are the markers), and so on: field(n) with n in those.
// Every failure is an InputError at the field's file:line:column naming the card, its id and
// the field ("CBAR 12, field 4 (GB): expected an integer, got '1.5'").
#pragma once

#include <optional>
#include <string>

#include "bulkdata/card_reader.h"

namespace limber::bulkdata {

class CardFields {
 public:
  explicit CardFields(const Card& card);

  const Card& card() const { return card_; }
  // The card and its id (field 2) for messages, e.g. "CBAR 12".
  std::string label() const;

  bool blank(int field) const;  // true beyond the card's last field too
  const std::string& text(int field) const;
  // The number of the last field that is not blank (1 for a card without data).
  int last_field() const;

  int integer(int field, const char* name) const;  // required
  int integer_or(int field, const char* name, int fallback) const;
  // A positive id (> 0), required.
  int id(int field, const char* name) const;
  double real(int field, const char* name) const;  // required
  double real_or(int field, const char* name, double fallback) const;
  std::optional<double> optional_real(int field, const char* name) const;
  // True when the field holds an integer (not a real): e.g. CBAR's G0 versus X1.
  bool is_integer(int field) const;

  // Throws InputError at the field (or at the card's first line for field <= 1).
  [[noreturn]] void fail(int field, const char* name, const std::string& message) const;
  [[noreturn]] void fail_card(const std::string& message) const;
  SourceLocation where(int field) const;

 private:
  const Field* find(int field) const;

  const Card& card_;
};

// Parses NASTRAN integer and real field text (rules above); nothing when the text is not one.
std::optional<int> parse_integer(const std::string& text);
std::optional<double> parse_real(const std::string& text);

}  // namespace limber::bulkdata
