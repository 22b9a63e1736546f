#include "file_stem.h"

namespace limber::render {

std::string file_stem(std::string_view text) {
  if (text.empty()) return "~";
  constexpr char kHex[] = "0123456789ABCDEF";
  std::string stem;
  for (const char c : text) {
    const auto u = static_cast<unsigned char>(c);
    const bool keep = (u >= 'A' && u <= 'Z') || (u >= 'a' && u <= 'z') || (u >= '0' && u <= '9') ||
                      u == '_' || u == '-';
    if (keep) {
      stem += c;
    } else {
      stem += '~';
      stem += kHex[u >> 4];
      stem += kHex[u & 0xF];
    }
  }
  return stem;
}

}  // namespace limber::render
