// Help text within 100 columns: CLI11 (2.1) prints an option's description from column 30 and
// does not wrap it, so a long description would run on as one line. Header-only (limber_cli),
// for every part that registers a sub-command.
#pragma once

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cstddef>
#include <string>

namespace limber::cli {

// Display width of UTF-8 text: its code points (no wide characters in our help).
inline std::size_t display_width(const std::string& text) {
  return static_cast<std::size_t>(
      std::count_if(text.begin(), text.end(), [](char c) { return (static_cast<unsigned char>(c) & 0xC0) != 0x80; }));
}

// `text` with line breaks between words so that no line is wider than `width` (a longer word
// stays whole); its own line breaks are kept.
inline std::string wrap_words(const std::string& text, std::size_t width) {
  std::string out;
  std::size_t line = 0;  // width of the current line
  std::size_t start = 0;
  while (start < text.size()) {
    const std::size_t end = std::min(text.find_first_of(" \n", start), text.size());
    const std::string word = text.substr(start, end - start);
    const std::size_t w = display_width(word);
    if (line > 0 && line + 1 + w > width) {
      out += '\n';
      line = 0;
    } else if (line > 0) {
      out += ' ';
      ++line;
    }
    out += word;
    line += w;
    if (end < text.size() && text[end] == '\n') {
      out += '\n';
      line = 0;
    }
    start = end + 1;
  }
  return out;
}

// Wraps the description of every option of `command` so that its help fits in `columns`
// (CLI11's default name column of 30 included).
inline void wrap_option_help(CLI::App& command, std::size_t columns = 100) {
  for (CLI::Option* option : command.get_options()) {
    option->description(wrap_words(option->get_description(), columns - 30));
  }
}

}  // namespace limber::cli
