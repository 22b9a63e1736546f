// Test helpers: a card written in small-field, large-field or free-field format, and where a
// piece of text sits in a deck.
#pragma once

#include <fmt/format.h>

#include <string>
#include <vector>

namespace limber::test {

enum class FieldFormat { kSmall, kLarge, kFree };

// `fields` are the name and the data fields in order (NASTRAN fields 2-9, 12-19, ...).
// Small: 8-column fields, explicit '+' continuations. Large: name with '*', 16-column fields,
// '*' continuations. Free: commas, implicit continuations (a leading comma).
inline std::string card_text(FieldFormat format, const std::vector<std::string>& fields) {
  const std::string& name = fields.front();
  const std::size_t per_line = format == FieldFormat::kLarge ? 4 : 8;
  std::string text;
  for (std::size_t start = 1, line = 0; start < fields.size() || line == 0;
       start += per_line, ++line) {
    const std::size_t end = std::min(fields.size(), start + per_line);
    switch (format) {
      case FieldFormat::kSmall:
        text += fmt::format("{:<8}", line == 0 ? name : "+");
        for (std::size_t k = start; k < end; ++k) text += fmt::format("{:>8}", fields[k]);
        break;
      case FieldFormat::kLarge:
        text += fmt::format("{:<8}", line == 0 ? name + "*" : "*");
        for (std::size_t k = start; k < end; ++k) text += fmt::format("{:<16}", fields[k]);
        break;
      case FieldFormat::kFree:
        text += line == 0 ? name : "";
        for (std::size_t k = start; k < end; ++k) text += "," + fields[k];
        break;
    }
    text += "\n";
  }
  return text;
}

// "deck.bdf:L:C" of the first appearance of `marker` in `text`.
inline std::string deck_location(const std::string& text, const std::string& marker,
                                 const std::string& file = "deck.bdf") {
  const std::size_t at = text.find(marker);
  if (at == std::string::npos) return "marker '" + marker + "' not in the deck";
  int line = 1;
  std::size_t line_start = 0;
  for (std::size_t i = 0; i < at; ++i) {
    if (text[i] == '\n') {
      ++line;
      line_start = i + 1;
    }
  }
  return fmt::format("{}:{}:{}", file, line, at - line_start + 1);
}

}  // namespace limber::test
