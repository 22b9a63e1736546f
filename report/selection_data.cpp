#include "selection_data.h"

#include <cstdlib>
#include <fstream>
#include <map>
#include <stdexcept>

namespace limber::report {
namespace {

// A malformed file: the message says where, what was expected and what was found.
struct Malformed : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// One CSV line split into fields; a field wrapped in double quotes may hold commas, and "" in
// it is one quote.
std::vector<std::string> split_csv_line(const std::string& line, int number) {
  std::vector<std::string> fields(1);
  bool quoted = false;
  for (std::size_t k = 0; k < line.size(); ++k) {
    const char c = line[k];
    std::string& field = fields.back();
    if (quoted) {
      if (c != '"') {
        field += c;
      } else if (k + 1 < line.size() && line[k + 1] == '"') {
        field += '"';
        ++k;
      } else {
        quoted = false;
      }
    } else if (c == ',') {
      fields.emplace_back();
    } else if (c == '"' && field.empty()) {
      quoted = true;
    } else {
      field += c;
    }
  }
  if (quoted) {
    throw Malformed("line " + std::to_string(number) + ": expected a closing double quote, got the end of the line");
  }
  return fields;
}

// A CSV file: its header and its rows, each with its line number.
struct CsvTable {
  std::vector<std::string> header;
  std::vector<std::pair<int, std::vector<std::string>>> rows;

  // Index of a required column.
  std::size_t column(const std::string& name) const {
    for (std::size_t c = 0; c < header.size(); ++c) {
      if (header[c] == name) return c;
    }
    throw Malformed("line 1: expected a column '" + name + "' in the header, got none");
  }
};

CsvTable read_csv(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw Malformed("cannot be opened");
  CsvTable table;
  std::string line;
  int number = 0;
  while (std::getline(in, line)) {
    ++number;
    // Windows line ends, a UTF-8 byte-order mark, blank lines.
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (number == 1 && line.rfind("\xEF\xBB\xBF", 0) == 0) line.erase(0, 3);
    if (line.empty()) continue;
    std::vector<std::string> fields = split_csv_line(line, number);
    if (table.header.empty()) {
      table.header = std::move(fields);
      continue;
    }
    if (fields.size() != table.header.size()) {
      throw Malformed("line " + std::to_string(number) + ": expected " +
                      std::to_string(table.header.size()) + " fields as in the header, got " +
                      std::to_string(fields.size()));
    }
    table.rows.emplace_back(number, std::move(fields));
  }
  if (table.header.empty()) throw Malformed("expected a header row, got an empty file");
  return table;
}

// Field `column` of a row as a number; nullopt when empty and allowed to be.
std::optional<double> number_field(const CsvTable& table, std::size_t row, std::size_t column,
                                   bool optional) {
  const auto& [line, fields] = table.rows[row];
  const std::string& text = fields[column];
  if (text.empty() && optional) return std::nullopt;
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (text.empty() || end != text.c_str() + text.size()) {
    throw Malformed("line " + std::to_string(line) + ": expected a number in column '" +
                    table.header[column] + "', got '" + text + "'");
  }
  return value;
}

double required_number(const CsvTable& table, std::size_t row, std::size_t column) {
  return *number_field(table, row, column, false);
}

long long integer_field(const CsvTable& table, std::size_t row, std::size_t column) {
  const double value = required_number(table, row, column);
  if (value != static_cast<double>(static_cast<long long>(value))) {
    throw Malformed("line " + std::to_string(table.rows[row].first) + ": expected an integer in column '" +
                    table.header[column] + "', got '" + table.rows[row].second[column] + "'");
  }
  return static_cast<long long>(value);
}

bool flag_field(const CsvTable& table, std::size_t row, std::size_t column) {
  const std::string& text = table.rows[row].second[column];
  if (text == "0") return false;
  if (text == "1") return true;
  throw Malformed("line " + std::to_string(table.rows[row].first) + ": expected 0 or 1 in column '" +
                  table.header[column] + "', got '" + text + "'");
}

std::vector<RankingRow> parse_ranking(const CsvTable& t) {
  const std::size_t body = t.column("body"), joint = t.column("joint"), node = t.column("node"),
                    quantity = t.column("quantity"), axis = t.column("axis"), peak = t.column("peak"),
                    rms = t.column("rms"), relative = t.column("relative"), kept = t.column("kept"),
                    indeterminate = t.column("indeterminate");
  std::vector<RankingRow> rows;
  for (std::size_t r = 0; r < t.rows.size(); ++r) {
    const std::vector<std::string>& f = t.rows[r].second;
    rows.push_back({f[body], f[joint], integer_field(t, r, node), f[quantity], f[axis],
                    required_number(t, r, peak), required_number(t, r, rms),
                    required_number(t, r, relative), flag_field(t, r, kept),
                    flag_field(t, r, indeterminate)});
  }
  return rows;
}

std::vector<ComparisonRow> parse_comparison(const CsvTable& t) {
  const std::size_t set = t.column("set"), description = t.column("description"),
                    modes = t.column("modes"), reduction = t.column("reduction_s"),
                    run = t.column("run_s"), status = t.column("status"),
                    error_peak = t.column("error_peak"), error_rms = t.column("error_rms"),
                    worst = t.column("worst_quantity"), directory = t.column("directory"),
                    role = t.column("role");
  std::vector<ComparisonRow> rows;
  for (std::size_t r = 0; r < t.rows.size(); ++r) {
    const std::vector<std::string>& f = t.rows[r].second;
    rows.push_back({f[set], f[description], integer_field(t, r, modes),
                    number_field(t, r, reduction, true), number_field(t, r, run, true), f[status],
                    number_field(t, r, error_peak, true), number_field(t, r, error_rms, true),
                    f[worst], f[directory], f[role]});
  }
  return rows;
}

// Columns "<set>|<quantity>" after "time"; an empty cell is a sample the set does not have.
std::vector<KeySeries> parse_key_series(const CsvTable& t) {
  if (t.header.front() != "time") {
    throw Malformed("line 1: expected 'time' as the first column, got '" + t.header.front() + "'");
  }
  std::vector<KeySeries> series;
  for (std::size_t c = 1; c < t.header.size(); ++c) {
    const std::size_t bar = t.header[c].find('|');
    if (bar == std::string::npos) {
      throw Malformed("line 1: expected a column named '<set>|<quantity>', got '" + t.header[c] + "'");
    }
    KeySeries s{t.header[c].substr(0, bar), t.header[c].substr(bar + 1), {}, {}};
    std::vector<double> time, values;
    for (std::size_t r = 0; r < t.rows.size(); ++r) {
      const std::optional<double> value = number_field(t, r, c, true);
      if (!value) continue;
      time.push_back(required_number(t, r, 0));
      values.push_back(*value);
    }
    s.time = Eigen::Map<const Eigen::VectorXd>(time.data(), static_cast<Eigen::Index>(time.size()));
    s.values = Eigen::Map<const Eigen::VectorXd>(values.data(), static_cast<Eigen::Index>(values.size()));
    series.push_back(std::move(s));
  }
  return series;
}

// Reads one file into `part`; a missing or malformed file becomes a note.
template <typename Part, typename Parse>
void read_part(const std::filesystem::path& folder, const char* name, Parse parse, Part& part,
               std::vector<std::string>& notes) {
  const std::filesystem::path file = folder / name;
  const std::string shown = std::string(kSelectionFolder) + "/" + name;
  std::error_code error;
  if (!std::filesystem::is_regular_file(file, error)) {
    notes.push_back(shown + " not found: the mode-selection section leaves it out.");
    return;
  }
  try {
    part = parse(read_csv(file));
  } catch (const Malformed& e) {
    notes.push_back(shown + " not shown: " + e.what() + ".");
  }
}

}  // namespace

std::optional<SelectionData> read_selection(const std::filesystem::path& run_directory,
                                            std::vector<std::string>& notes) {
  const std::filesystem::path folder = run_directory / kSelectionFolder;
  std::error_code error;
  if (!std::filesystem::is_directory(folder, error)) return std::nullopt;
  SelectionData selection;
  selection.directory = folder;
  read_part(folder, kRankingFile, parse_ranking, selection.ranking, notes);
  read_part(folder, kComparisonFile, parse_comparison, selection.comparison, notes);
  read_part(folder, kKeySeriesFile, parse_key_series, selection.key_series, notes);
  return selection;
}

}  // namespace limber::report
