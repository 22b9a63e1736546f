// Test helpers: where a piece of text sits in an inline case, and checks that a case fails
// with an InputError at that place with the expected words: in the read stage, or for the
// checks that need the modes (per-mode list lengths), in the build after the reduction.
#pragma once

#include <gtest/gtest.h>

#include <string>

#include "core/error.h"
#include "io/case_reader.h"
#include "io/case_reduction.h"
#include "io/mechanism_builder.h"

namespace limber::test {

inline constexpr const char* kCaseName = "test.yaml";

// "test.yaml:L:C" of the `occurrence`-th (0-based) appearance of `marker` in `text`.
inline std::string location_of(const std::string& text, const std::string& marker,
                               int occurrence = 0) {
  std::size_t at = text.find(marker);
  for (int k = 0; k < occurrence && at != std::string::npos; ++k) at = text.find(marker, at + 1);
  if (at == std::string::npos) return "marker '" + marker + "' not in the case text";
  int line = 1;
  std::size_t line_start = 0;
  for (std::size_t i = 0; i < at; ++i) {
    if (text[i] == '\n') {
      ++line;
      line_start = i + 1;
    }
  }
  return std::string(kCaseName) + ":" + std::to_string(line) + ":" +
         std::to_string(at - line_start + 1);
}

// `text` with the first `from` replaced by `to` (which must be there).
inline std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return at == std::string::npos ? text : text.replace(at, from.size(), to);
}

// Reads `text` (and reduces and builds its mechanism, if any); expects an InputError
// located at `where` whose message holds `words`.
inline ::testing::AssertionResult fails_at(const std::string& text, const std::string& where,
                                           const std::string& words) {
  try {
    const io::Case input = io::read_case_text(text, kCaseName);
    if (input.mechanism) {
      io::build_mechanism(input, io::reduce_case(input, io::ReductionScope::kMechanismBodies));
    }
  } catch (const InputError& error) {
    const std::string got = error.what();
    if (got.rfind(where + ": ", 0) != 0) {
      return ::testing::AssertionFailure() << "expected the location " << where << ", got: " << got;
    }
    if (got.find(words) == std::string::npos) {
      return ::testing::AssertionFailure() << "expected the words '" << words << "', got: " << got;
    }
    return ::testing::AssertionSuccess() << got;
  }
  return ::testing::AssertionFailure() << "expected an InputError, got none";
}

}  // namespace limber::test
