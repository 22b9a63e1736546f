#include "results/link_name.h"

#include "core/error.h"

namespace limber::results {

std::string link_name(std::string_view name) {
  LIMBER_DEMAND(!name.empty());
  constexpr char kHex[] = "0123456789ABCDEF";
  std::string link;
  link.reserve(name.size());
  for (std::size_t k = 0; k < name.size(); ++k) {
    const auto c = static_cast<unsigned char>(name[k]);
    // Escape what HDF5 cannot hold or would misread, and the escape character itself.
    const bool escape = c == '%' || c == '/' || c < 0x20 || c == 0x7F || (k == 0 && c == '.');
    if (escape) {
      link += '%';
      link += kHex[c >> 4];
      link += kHex[c & 0xF];
    } else {
      link += static_cast<char>(c);
    }
  }
  return link;
}

}  // namespace limber::results
