// Pieces of JSON text (RFC 8259) for machine-readable output: the commands' --json, the run
// record (run/run_record.h), the sweep's and the selection's documents.
#pragma once

#include <cstddef>
#include <string>

namespace limber {

// `text` as a quoted JSON string (quotes, backslashes and control characters escaped).
std::string json_string(const std::string& text);

// `value` in the shortest form that reads back exactly; null when not finite.
std::string json_number(double value);

// The JSON string whose opening quote is text[at], unescaped (\uXXXX above ASCII becomes '?');
// `at` is left just after its closing quote (or at the end of an unterminated string).
std::string json_read_string(const std::string& text, std::size_t& at);

}  // namespace limber
