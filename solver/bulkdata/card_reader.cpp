#include "bulkdata/card_reader.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string_view>

#include "core/input_file.h"

namespace limber::bulkdata {

namespace {

constexpr int kNameWidth = 8;
constexpr int kSmallWidth = 8;
constexpr int kLargeWidth = 16;
constexpr int kSmallFieldsPerLine = 8;
constexpr int kLargeFieldsPerLine = 4;
constexpr int kTabStop = 8;
// Deeper nesting than this is surely a mistake even without a cycle.
constexpr std::size_t kMaxIncludeDepth = 64;

std::string upper(std::string_view text) {
  std::string result(text);
  for (char& c : result) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return result;
}

bool is_blank(char c) { return c == ' ' || c == '\r' || c == '\f' || c == '\v'; }

// Text without leading and trailing blanks, and the offset of its first character.
std::pair<std::string_view, std::size_t> trimmed(std::string_view text) {
  std::size_t first = 0;
  while (first < text.size() && is_blank(text[first])) ++first;
  std::size_t last = text.size();
  while (last > first && is_blank(text[last - 1])) --last;
  return {text.substr(first, last - first), first};
}

// The line with tabs moved to the next tab stop and the comment ('$' onwards) removed.
std::string clean_line(std::string_view raw) {
  std::string line;
  for (char c : raw) {
    if (c == '$') break;
    if (c == '\t') {
      line.append(kTabStop - line.size() % kTabStop, ' ');
    } else {
      line.push_back(c);
    }
  }
  return line;
}

std::vector<std::string> split_lines(const std::string& text) {
  std::vector<std::string> lines;
  std::string line;
  std::istringstream stream(text);
  while (std::getline(stream, line)) lines.push_back(line);
  return lines;
}

// True when the trimmed upper-case line starts with `keyword` followed by a blank or the end.
bool starts_with_keyword(std::string_view line_upper, std::string_view keyword) {
  if (line_upper.substr(0, keyword.size()) != keyword) return false;
  return line_upper.size() == keyword.size() || is_blank(line_upper[keyword.size()]) ||
         line_upper[keyword.size()] == '\'' || line_upper[keyword.size()] == '"';
}

// "BEGIN BULK" (any spacing), the line after which a main file's bulk data starts.
bool is_begin_bulk(std::string_view line_upper) {
  if (!starts_with_keyword(line_upper, "BEGIN")) return false;
  const auto [rest, offset] = trimmed(line_upper.substr(5));
  return rest.substr(0, 4) == "BULK";
}

// A card name: a letter, then letters and digits.
bool is_card_name(std::string_view name) {
  if (name.empty() || !std::isalpha(static_cast<unsigned char>(name[0]))) return false;
  return std::all_of(name.begin(), name.end(),
                     [](char c) { return std::isalnum(static_cast<unsigned char>(c)) != 0; });
}

std::string read_whole_file(const std::string& path, const SourceLocation& where) {
  const std::string problem = regular_file_problem(path);
  if (!problem.empty()) {
    throw InputError(fmt::format("expected a bulk-data file, got '{}' ({})", abbreviated(path), problem),
                     where);
  }
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  if (!in) {
    throw InputError(fmt::format("expected a readable bulk-data file, got '{}'", abbreviated(path)), where);
  }
  return text.str();
}

class Reader {
 public:
  std::vector<Card> cards;

  void read_file(const std::string& path, const SourceLocation& where, bool main) {
    read_text(read_whole_file(path, where), path, main);
  }

  void read_text(const std::string& text, const std::string& path, bool main) {
    // Include cycles: the same file already being read.
    std::error_code error;
    std::string key = std::filesystem::weakly_canonical(path, error).string();
    if (error) key = path;
    if (std::find(stack_.begin(), stack_.end(), key) != stack_.end()) {
      std::string chain;
      for (const std::string& file : stack_) chain += file + " -> ";
      throw InputError(fmt::format("expected INCLUDE files without a cycle, got {}{}", chain, key),
                       including_);
    }
    if (stack_.size() >= kMaxIncludeDepth) {
      throw InputError(
          fmt::format("expected INCLUDE nesting of at most {} files", kMaxIncludeDepth),
          including_);
    }
    stack_.push_back(key);
    const auto file = std::make_shared<const std::string>(path);
    const std::vector<std::string> lines = split_lines(text);

    // A main file's bulk data starts after BEGIN BULK, when it has one.
    std::size_t first = 0;
    if (main) {
      for (std::size_t i = 0; i < lines.size(); ++i) {
        if (is_begin_bulk(upper(trimmed(clean_line(lines[i])).first))) {
          first = i + 1;
          break;
        }
      }
      // Executive and case control without BEGIN BULK: not a deck limber can read.
      for (std::size_t i = 0; first == 0 && i < lines.size(); ++i) {
        if (starts_with_keyword(upper(trimmed(clean_line(lines[i])).first), "CEND")) {
          throw InputError("expected BEGIN BULK after the case control (CEND), got none",
                           {path, static_cast<int>(i) + 1, 1});
        }
      }
    }

    if (first > 0) case_control_sets(lines, first, file);
    open_ = false;
    for (std::size_t i = first; i < lines.size() && !ended_; ++i) {
      read_line(clean_line(lines[i]), file, static_cast<int>(i) + 1);
    }
    open_ = false;
    stack_.pop_back();
  }

 private:
  std::vector<std::string> stack_;  // files being read, outermost first
  SourceLocation including_;        // the INCLUDE being followed
  bool open_ = false;               // cards.back() may take continuation lines
  bool open_large_ = false;         // ... and was started in large-field format
  bool ended_ = false;              // ENDDATA seen
  std::size_t target_ = 0;          // the card continuation lines add to
  std::vector<bool> large_;         // per card: started in large-field format
  std::map<std::string, std::size_t> awaiting_;  // field-10 marker -> its card

  // Case-control "SET n = id, id THRU id, ..." lines (after CEND, before BEGIN BULK; a line
  // ending in a comma continues) as cards named SET: the id, then the members, THRU kept.
  // Sets of other forms (ALL, EXCEPT, BY, reals) name no list of grids and are skipped.
  void case_control_sets(const std::vector<std::string>& lines, std::size_t first,
                         const std::shared_ptr<const std::string>& file) {
    std::size_t start = 0;
    for (std::size_t i = 0; i + 1 < first; ++i) {
      if (starts_with_keyword(upper(trimmed(clean_line(lines[i])).first), "CEND")) start = i + 1;
    }
    for (std::size_t i = start; i + 1 < first; ++i) {
      const std::string head = upper(trimmed(clean_line(lines[i])).first);
      if (!starts_with_keyword(head, "SET")) continue;
      // The tokens of the set's lines, with their places.
      Card card;
      card.name = "SET";
      card.file = file;
      card.line = static_cast<int>(i) + 1;
      bool readable = true, equals = false;
      for (std::size_t k = i; k + 1 < first; ++k) {
        const std::string line = upper(clean_line(lines[k]));
        std::size_t at = k == i ? line.find("SET") + 3 : 0;
        while (at < line.size()) {
          if (line[at] == ',' || is_blank(line[at])) {
            ++at;
            continue;
          }
          if (line[at] == '=') {
            if (equals || card.fields.size() != 1) readable = false;
            equals = true;
            ++at;
            continue;
          }
          std::size_t end = at;
          while (end < line.size() && line[end] != ',' && line[end] != '=' && !is_blank(line[end])) ++end;
          const std::string token = line.substr(at, end - at);
          const bool digits = std::all_of(token.begin(), token.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; });
          if (!digits && token != "THRU") readable = false;
          card.fields.push_back({token, static_cast<int>(k) + 1, static_cast<int>(at) + 1});
          at = end;
        }
        const std::string_view rest = trimmed(line).first;
        i = k;
        if (rest.empty() || rest.back() != ',') break;
      }
      if (readable && equals && card.fields.size() >= 2) cards.push_back(std::move(card));
    }
  }

  void read_line(const std::string& line, const std::shared_ptr<const std::string>& file,
                 int number) {
    const auto [content, offset] = trimmed(line);
    if (content.empty()) return;
    const std::string head = upper(content.substr(0, 16));
    const SourceLocation where{*file, number, static_cast<int>(offset) + 1};

    // Deck structure: end, includes, a stray BEGIN BULK in an include.
    if (starts_with_keyword(head, "ENDDATA")) {
      ended_ = true;
      return;
    }
    if (starts_with_keyword(head, "INCLUDE")) {
      include(std::string(content.substr(7)), *file, where);
      return;
    }
    if (is_begin_bulk(upper(content))) return;

    if (line.find(',') != std::string::npos) {
      read_free_line(line, file, number);
    } else {
      read_fixed_line(line, file, number);
    }
  }

  // A continuation marker without its '+' or '*' (markers match whatever their first mark).
  static std::string marker_key(std::string_view marker) {
    const auto [text, offset] = trimmed(marker);
    if (text.empty()) return {};
    return upper(text[0] == '+' || text[0] == '*' ? text.substr(1) : text);
  }

  // The marker in field 10 of the line just read: a later continuation line that names it
  // continues this card, wherever it is in the deck.
  void end_line(std::string_view marker) {
    const std::string key = marker_key(marker);
    if (!key.empty()) awaiting_[key] = target_;
  }

  // Starts a card or checks that a continuation has one; returns the line's large-field flag.
  // A continuation whose marker matches an earlier card's field 10 continues that card; one
  // without a match continues the card above it.
  bool start_line(std::string_view first, const std::shared_ptr<const std::string>& file,
                  int number, int column) {
    const bool continuation = first.empty() || first[0] == '+' || first[0] == '*';
    if (continuation) {
      const std::string key = marker_key(first);
      if (const auto found = key.empty() ? awaiting_.end() : awaiting_.find(key); found != awaiting_.end()) {
        target_ = found->second;
        awaiting_.erase(found);
        open_ = true;
        open_large_ = large_[target_];
      }
      if (!open_) {
        throw InputError(
            "expected a card name in field 1, got a continuation line with no card before it "
            "(and no card whose continuation marker in field 10 matches it)",
            {*file, number, column});
      }
      return (!first.empty() && first[0] == '*') || (first.empty() && open_large_);
    }
    std::string name = upper(first);
    const bool large = name.back() == '*';
    if (large) name.pop_back();
    if (!is_card_name(name)) {
      throw InputError(fmt::format("expected a card name (a letter, then letters and digits) in "
                                   "field 1, got '{}'",
                                   first),
                       {*file, number, column});
    }
    Card card;
    card.name = std::move(name);
    card.file = file;
    card.line = number;
    cards.push_back(std::move(card));
    target_ = cards.size() - 1;
    large_.push_back(large);
    open_ = true;
    open_large_ = large;
    return large;
  }

  void add_field(std::string_view text, int number, int column) {
    const auto [content, offset] = trimmed(text);
    cards[target_].fields.push_back(
        {upper(content), number, column + static_cast<int>(content.empty() ? 0 : offset)});
  }

  void read_fixed_line(const std::string& line, const std::shared_ptr<const std::string>& file,
                       int number) {
    const std::string_view view(line);
    const auto [first, offset] = trimmed(view.substr(0, kNameWidth));
    const bool large = start_line(first, file, number, static_cast<int>(offset) + 1);
    const int width = large ? kLargeWidth : kSmallWidth;
    const int count = large ? kLargeFieldsPerLine : kSmallFieldsPerLine;
    // Columns 73-80 hold the continuation marker; beyond them nothing is read.
    for (int k = 0; k < count; ++k) {
      const std::size_t start = kNameWidth + static_cast<std::size_t>(k) * width;
      const std::string_view text = start < view.size() ? view.substr(start, width) : "";
      add_field(text, number, static_cast<int>(start) + 1);
    }
    constexpr std::size_t kMarkerColumn = 72;
    end_line(view.size() > kMarkerColumn ? view.substr(kMarkerColumn, kSmallWidth) : "");
  }

  void read_free_line(const std::string& line, const std::shared_ptr<const std::string>& file,
                      int number) {
    // Comma-separated tokens with their columns.
    std::vector<std::pair<std::string_view, int>> tokens;
    std::size_t start = 0;
    const std::string_view view(line);
    while (true) {
      const std::size_t comma = view.find(',', start);
      const std::size_t end = comma == std::string_view::npos ? view.size() : comma;
      tokens.emplace_back(view.substr(start, end - start), static_cast<int>(start) + 1);
      if (comma == std::string_view::npos) break;
      start = comma + 1;
    }
    const auto [first, offset] = trimmed(tokens[0].first);
    const bool large = start_line(first, file, number, tokens[0].second + static_cast<int>(offset));
    const int count = large ? kLargeFieldsPerLine : kSmallFieldsPerLine;
    // Name, data fields and an optional continuation marker.
    if (static_cast<int>(tokens.size()) > count + 2) {
      throw InputError(fmt::format("expected at most {} fields on a free-field {} line (name, {} "
                                   "data fields, continuation), got {}",
                                   count + 2, large ? "large-field" : "small-field", count,
                                   tokens.size()),
                       {*file, number, tokens[count + 2].second});
    }
    for (int k = 1; k <= count; ++k) {
      if (k < static_cast<int>(tokens.size())) {
        add_field(tokens[k].first, number, tokens[k].second);
      } else {
        add_field("", number, 0);
      }
    }
    end_line(static_cast<int>(tokens.size()) == count + 2 ? tokens[count + 1].first : "");
  }

  void include(const std::string& argument, const std::string& file, const SourceLocation& where) {
    // The path: quoted, or the rest of the line.
    const auto [text, offset] = trimmed(argument);
    std::string path(text);
    if (!text.empty() && (text[0] == '\'' || text[0] == '"')) {
      const std::size_t close = text.find(text[0], 1);
      if (close == std::string_view::npos) {
        throw InputError("expected INCLUDE 'path' with a closing quote, got " + std::string(text),
                         where);
      }
      path = std::string(text.substr(1, close - 1));
    }
    if (path.empty()) throw InputError("expected a file name after INCLUDE, got none", where);

    // Relative to the including file's folder.
    std::filesystem::path resolved(path);
    if (resolved.is_relative()) resolved = std::filesystem::path(file).parent_path() / resolved;
    open_ = false;
    const SourceLocation outer = including_;
    including_ = where;
    read_file(resolved.string(), where, false);
    including_ = outer;
    open_ = false;
  }
};

}  // namespace

std::vector<Card> read_cards(const std::string& path, const SourceLocation& where) {
  Reader reader;
  reader.read_file(path, where, true);
  return std::move(reader.cards);
}

std::vector<Card> read_cards_text(const std::string& text, const std::string& file) {
  Reader reader;
  reader.read_text(text, file, true);
  return std::move(reader.cards);
}

}  // namespace limber::bulkdata
