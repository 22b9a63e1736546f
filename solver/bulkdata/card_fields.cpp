#include "bulkdata/card_fields.h"

#include <fmt/format.h>

#include <cctype>
#include <charconv>
#include <cmath>

namespace limber::bulkdata {

namespace {

constexpr int kFieldsPerLine = 10;
constexpr int kDataPerLine = 8;

bool is_digit(char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; }

// Index into Card::fields of NASTRAN field `field`, or -1 for a name or marker field.
int data_index(int field) {
  if (field < 2) return -1;
  const int line = (field - 1) / kFieldsPerLine;
  const int slot = (field - 1) % kFieldsPerLine;  // 0: name or marker, 1-8: data, 9: marker
  if (slot == 0 || slot == 9) return -1;
  return line * kDataPerLine + slot - 1;
}

const std::string kBlank;

}  // namespace

std::optional<int> parse_integer(const std::string& text) {
  std::size_t start = text.size() > 0 && text[0] == '+' ? 1 : 0;
  if (start >= text.size()) return std::nullopt;
  int value = 0;
  const char* end = text.data() + text.size();
  const auto [last, error] = std::from_chars(text.data() + start, end, value);
  if (error != std::errc() || last != end) return std::nullopt;
  return value;
}

std::optional<double> parse_real(const std::string& text) {
  // Mantissa: sign, digits, a decimal point, digits (at least one digit in all).
  std::size_t i = 0;
  std::string normal;
  if (i < text.size() && (text[i] == '+' || text[i] == '-')) {
    if (text[i] == '-') normal.push_back('-');
    ++i;
  }
  int digits = 0;
  bool point = false;
  for (; i < text.size(); ++i) {
    if (is_digit(text[i])) {
      ++digits;
    } else if (text[i] == '.' && !point) {
      point = true;
    } else {
      break;
    }
    normal.push_back(text[i]);
  }
  if (digits == 0 || !point) return std::nullopt;

  // Exponent: E or D with an optional sign, or a bare sign; then digits.
  if (i < text.size()) {
    if (text[i] == 'E' || text[i] == 'D') ++i;
    else if (text[i] != '+' && text[i] != '-') return std::nullopt;
    normal.push_back('e');
    if (i < text.size() && (text[i] == '+' || text[i] == '-')) normal.push_back(text[i++]);
    const std::size_t exponent_start = i;
    for (; i < text.size() && is_digit(text[i]); ++i) normal.push_back(text[i]);
    if (i == exponent_start || i != text.size()) return std::nullopt;
  }

  double value = 0.0;
  const char* end = normal.data() + normal.size();
  const auto [last, error] = std::from_chars(normal.data(), end, value);
  if (error != std::errc() || last != end || !std::isfinite(value)) return std::nullopt;
  return value;
}

CardFields::CardFields(const Card& card) : card_(card) {}

const Field* CardFields::find(int field) const {
  const int index = data_index(field);
  if (index < 0 || index >= static_cast<int>(card_.fields.size())) return nullptr;
  return &card_.fields[index];
}

std::string CardFields::label() const {
  const std::string& id = text(2);
  return id.empty() ? card_.name : card_.name + " " + id;
}

bool CardFields::blank(int field) const { return text(field).empty(); }

const std::string& CardFields::text(int field) const {
  const Field* found = find(field);
  return found ? found->text : kBlank;
}

int CardFields::last_field() const {
  for (int index = static_cast<int>(card_.fields.size()) - 1; index >= 0; --index) {
    if (!card_.fields[index].text.empty()) {
      return (index / kDataPerLine) * kFieldsPerLine + index % kDataPerLine + 2;
    }
  }
  return 1;
}

SourceLocation CardFields::where(int field) const {
  const Field* found = find(field);
  if (!found || found->column == 0) return card_.where();
  return card_.where(*found);
}

void CardFields::fail(int field, const char* name, const std::string& message) const {
  throw InputError(fmt::format("{}, field {} ({}): {}", label(), field, name, message),
                   where(field));
}

void CardFields::fail_card(const std::string& message) const {
  throw InputError(fmt::format("{}: {}", label(), message), card_.where());
}

bool CardFields::is_integer(int field) const { return parse_integer(text(field)).has_value(); }

int CardFields::integer(int field, const char* name) const {
  if (blank(field)) fail(field, name, "expected an integer, got a blank field");
  const std::optional<int> value = parse_integer(text(field));
  if (!value) fail(field, name, fmt::format("expected an integer, got '{}'", text(field)));
  return *value;
}

int CardFields::integer_or(int field, const char* name, int fallback) const {
  return blank(field) ? fallback : integer(field, name);
}

int CardFields::id(int field, const char* name) const {
  const int value = integer(field, name);
  if (value <= 0) fail(field, name, fmt::format("expected a positive id, got {}", value));
  return value;
}

double CardFields::real(int field, const char* name) const {
  if (blank(field)) fail(field, name, "expected a real number, got a blank field");
  const std::optional<double> value = parse_real(text(field));
  if (!value) {
    fail(field, name,
         fmt::format("expected a real number with a decimal point (e.g. 7.0E10), got '{}'",
                     text(field)));
  }
  return *value;
}

double CardFields::real_or(int field, const char* name, double fallback) const {
  return blank(field) ? fallback : real(field, name);
}

std::optional<double> CardFields::optional_real(int field, const char* name) const {
  if (blank(field)) return std::nullopt;
  return real(field, name);
}

}  // namespace limber::bulkdata
