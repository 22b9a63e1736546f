#include "html.h"

#include <cstdio>

namespace limber::report {

namespace {

bool url_safe(unsigned char c) {
  return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '.' ||
         c == '_' || c == '~' || c == '-';
}

}  // namespace

std::string relative_url(const std::filesystem::path& from, const std::filesystem::path& to) {
  const std::filesystem::path relative =
      std::filesystem::weakly_canonical(to).lexically_relative(std::filesystem::weakly_canonical(from));
  std::string url;
  for (const std::filesystem::path& part : relative) {
    if (!url.empty()) url += '/';
    for (unsigned char c : part.string()) {
      if (url_safe(c)) {
        url += static_cast<char>(c);
      } else {
        char hex[4];
        std::snprintf(hex, sizeof hex, "%%%02X", c);
        url += hex;
      }
    }
  }
  return url;
}

std::string readable_stem(const std::string& text) {
  std::string out = text;
  for (char& c : out) {
    const auto u = static_cast<unsigned char>(c);
    const bool keep = (u >= 'A' && u <= 'Z') || (u >= 'a' && u <= 'z') || (u >= '0' && u <= '9') ||
                      u == '_' || u == '-';
    if (!keep) c = '_';
  }
  return out.empty() ? "_" : out;
}

}  // namespace limber::report
