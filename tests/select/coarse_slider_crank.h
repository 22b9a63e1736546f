// The shipped flexible slider-crank (cases/slider_crank.yaml) with its rod meshed by 20 beams
// instead of 100, for selection tests that run it several times: the rod's five lowest
// frequencies move by less than 0.1 % at that mesh (cubic beam elements converge fast).
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "run_test_support.h"

namespace limber::test {

inline std::string coarse_slider_crank_text() {
  const std::vector<std::pair<std::string, std::string>> edits = {
      {"elements: 100", "elements: 20"},
      {"R3: [101]", "R3: [21]"},
      {"{node: 51, chord", "{node: 11, chord"},
      {"t_end: 1.0 ", "t_end: 0.3 "},
  };
  std::string text = read_text(std::string(LIMBER_CASES_DIR) + "/slider_crank.yaml");
  for (const auto& [from, to] : edits) {
    const std::size_t at = text.find(from);
    if (at == std::string::npos) throw std::runtime_error("coarse_slider_crank: '" + from + "' not found");
    text.replace(at, from.size(), to);
  }
  return text;
}

// The coarse case written to a temp file; its path.
inline std::string coarse_slider_crank_file() { return write_case("coarse_slider_crank", coarse_slider_crank_text()); }

}  // namespace limber::test
