#include "core/json_text.h"

#include <fmt/format.h>

#include <cmath>
#include <cstdlib>

namespace limber {

std::string json_string(const std::string& text) {
  std::string out = "\"";
  for (char c : text) {
    switch (c) {
      case '"':
        out += "\\\"";
        break;
      case '\\':
        out += "\\\\";
        break;
      case '\n':
        out += "\\n";
        break;
      case '\t':
        out += "\\t";
        break;
      case '\r':
        out += "\\r";
        break;
      default:
        // Other control characters as \u00XX; everything else (UTF-8 included) as is.
        if (static_cast<unsigned char>(c) < 0x20) {
          out += fmt::format("\\u{:04x}", static_cast<int>(c));
        } else {
          out += c;
        }
    }
  }
  return out + "\"";
}

std::string json_number(double value) {
  if (!std::isfinite(value)) return "null";
  return fmt::format("{}", value);
}

std::string json_read_string(const std::string& text, std::size_t& at) {
  std::string value;
  for (++at; at < text.size() && text[at] != '"'; ++at) {
    if (text[at] != '\\' || at + 1 >= text.size()) {
      value += text[at];
      continue;
    }
    const char escaped = text[++at];
    switch (escaped) {
      case 'n': value += '\n'; break;
      case 't': value += '\t'; break;
      case 'r': value += '\r'; break;
      case 'b': value += '\b'; break;
      case 'f': value += '\f'; break;
      case 'u': {
        const long code = at + 4 < text.size() ? std::strtol(text.substr(at + 1, 4).c_str(), nullptr, 16) : 0;
        value += code > 0 && code < 128 ? static_cast<char>(code) : '?';
        at += 4;
        break;
      }
      default: value += escaped;  // \" \\ \/
    }
  }
  if (at < text.size()) ++at;
  return value;
}

}  // namespace limber
