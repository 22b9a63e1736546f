// Fields of the flat JSON objects (written with core/json_text.h) `limber sweep` reads back:
// its own process.json and the rows MPI ranks send (the run record has its own reader,
// run/run_record.h). A field is found by its key anywhere in the text, so only keys
// that occur once in the object may be read (true of process.json's keys and of a row's
// scalar fields, read before its "errors" list).
#pragma once

#include <optional>
#include <string>

namespace limber::sweep {

// The number after `"key": `; nullopt when absent or null.
std::optional<double> json_number_field(const std::string& text, const std::string& key);

// The string after `"key": `, unescaped (\uXXXX above ASCII becomes '?'); nullopt when absent.
std::optional<std::string> json_string_field(const std::string& text, const std::string& key);

}  // namespace limber::sweep
