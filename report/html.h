// Small pieces of HTML writing: escaping text from files, and relative links.
#pragma once

#include <filesystem>
#include <string>

namespace limber::report {

// Escapes & < > " ' so any text (titles, names, messages from results files) is shown as text,
// in element content and in quoted attribute values alike.
std::string html_escape(const std::string& text);

// A relative URL from directory `from` to file `to`: path components joined by '/',
// every byte outside [A-Za-z0-9._~-] percent-encoded.
std::string relative_url(const std::filesystem::path& from, const std::filesystem::path& to);

// A file name made of [A-Za-z0-9_-] from arbitrary text (other bytes become '_').
std::string file_stem(const std::string& text);

}  // namespace limber::report
