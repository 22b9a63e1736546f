// Small pieces of HTML writing: escaping text from files (core/markup_escape.h), and relative
// links.
#pragma once

#include <filesystem>
#include <string>

#include "core/markup_escape.h"
#include "file_stem.h"

namespace limber::report {

// A relative URL from directory `from` to file `to`: path components joined by '/',
// every byte outside [A-Za-z0-9._~-] percent-encoded.
std::string relative_url(const std::filesystem::path& from, const std::filesystem::path& to);

// A file name part from arbitrary text, injective and made of [A-Za-z0-9_~-]
// (render/file_stem.h, shared with render's VTU files).
using render::file_stem;

// A readable file name part from arbitrary text: [A-Za-z0-9_-], other bytes become '_'. Safe
// but not injective: only for texts numbered apart (selection quantities); names use file_stem.
std::string readable_stem(const std::string& text);

}  // namespace limber::report
