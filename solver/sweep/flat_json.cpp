#include "sweep/flat_json.h"

#include "core/json_text.h"

#include <cstdlib>

namespace limber::sweep {

namespace {

// Position just after `"key":` and its spaces, or npos.
std::size_t value_start(const std::string& text, const std::string& key) {
  const std::string needle = "\"" + key + "\":";
  std::size_t at = text.find(needle);
  if (at == std::string::npos) return at;
  at += needle.size();
  while (at < text.size() && (text[at] == ' ' || text[at] == '\n' || text[at] == '\t')) ++at;
  return at;
}

}  // namespace

std::optional<double> json_number_field(const std::string& text, const std::string& key) {
  const std::size_t at = value_start(text, key);
  if (at == std::string::npos || at >= text.size()) return std::nullopt;
  char* end = nullptr;
  const double value = std::strtod(text.c_str() + at, &end);
  if (end == text.c_str() + at) return std::nullopt;  // null or not a number
  return value;
}

std::optional<std::string> json_string_field(const std::string& text, const std::string& key) {
  std::size_t at = value_start(text, key);
  if (at == std::string::npos || at >= text.size() || text[at] != '"') return std::nullopt;
  return json_read_string(text, at);
}

}  // namespace limber::sweep
