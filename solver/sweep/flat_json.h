// Fields of the flat JSON objects (written with core/json_text.h) `limber sweep` reads back: `limber run --json`'s output and
// the sweep's own process.json. A field is found by its key anywhere in the text, so only keys
// that occur once in the object may be read (true of every key read here: "status", "wall_s",
// "steps", ..., "energy_relative" inside "accuracy").
#pragma once

#include <optional>
#include <string>

namespace limber::sweep {

// The number after `"key": `; nullopt when absent or null.
std::optional<double> json_number_field(const std::string& text, const std::string& key);

// The string after `"key": `, unescaped (\uXXXX above ASCII becomes '?'); nullopt when absent.
std::optional<std::string> json_string_field(const std::string& text, const std::string& key);

}  // namespace limber::sweep
