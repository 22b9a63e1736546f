// A small JSON reader (RFC 8259 subset without \u escapes beyond ASCII) so the CLI
// tests can check `limber --json` output; throws std::runtime_error on malformed text.
#pragma once

#include <map>
#include <memory>
#include <string>
#include <variant>
#include <vector>

namespace limber::test {

struct JsonValue {
  using Object = std::map<std::string, JsonValue>;
  using Array = std::vector<JsonValue>;
  std::variant<std::nullptr_t, bool, double, std::string, Array, Object> value;

  const JsonValue& operator[](const std::string& key) const;  // throws when absent
  const Array& array() const { return std::get<Array>(value); }
  const Object& object() const { return std::get<Object>(value); }
  const std::string& string() const { return std::get<std::string>(value); }
  double number() const { return std::get<double>(value); }
};

// Parses exactly one JSON value (surrounding whitespace allowed, nothing else).
JsonValue parse_json(const std::string& text);

}  // namespace limber::test
