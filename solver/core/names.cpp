#include "core/names.h"

#include <cstdio>

#include "core/input_file.h"

namespace limber {
namespace {

bool is_control(char c) {
  const auto u = static_cast<unsigned char>(c);
  return u < 0x20 || u == 0x7F;
}

std::string hex_byte(char c) {
  char text[8];
  std::snprintf(text, sizeof text, "%02X", static_cast<unsigned>(static_cast<unsigned char>(c)));
  return text;
}

}  // namespace

std::string printable_name(std::string_view name) {
  std::string out;
  for (char c : name) out += is_control(c) ? "\\x" + hex_byte(c) : std::string(1, c);
  return out;
}

void check_name_text(std::string_view what, std::string_view name, const SourceLocation& where) {
  const std::string kind(what);
  if (name.empty()) throw InputError(kind + " name: expected a non-empty name, got \"\"", where);
  if (name.size() > kMaxNameBytes) {
    throw InputError(kind + " name: expected at most " + std::to_string(kMaxNameBytes) +
                         " bytes, got \"" + printable_name(abbreviated(name)) + "\"",
                     where);
  }
  // The first control character, with its 0-based byte position.
  for (std::size_t k = 0; k < name.size(); ++k) {
    if (!is_control(name[k])) continue;
    throw InputError(kind + " name: expected text without control characters, got \"" +
                         printable_name(name) + "\" (byte 0x" + hex_byte(name[k]) + " at " +
                         std::to_string(k) + ")",
                     where);
  }
}

}  // namespace limber
