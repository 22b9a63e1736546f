// Text from input files in limber's messages and files. Files named in input files (a case's
// `base` and `bulk_data`, a deck's INCLUDE) are checked before they are opened, so that a bad
// name ends as an InputError at its place in the input, never as a filesystem exception (a name
// of a few thousand characters once did: issue 31); long text is shown abbreviated.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>

namespace limber {

// Why `path` cannot be read as a regular file: "" when it can, else "no such file", "file name
// too long", "not a regular file" or the system's words. Never throws.
std::string regular_file_problem(const std::filesystem::path& path);

// `text` for a message: as it is up to `kept` + 20 bytes, else its first `kept` bytes (whole
// UTF-8 characters), "…" and its length: 4000 times 'a' is 60 times 'a' and "… (4000 bytes)".
std::string abbreviated(std::string_view text, std::size_t kept = 60);

}  // namespace limber
