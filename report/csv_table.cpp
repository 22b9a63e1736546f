#include "csv_table.h"

#include <cstdlib>
#include <fstream>

namespace limber::report {

namespace {

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

}  // namespace

std::size_t CsvTable::column(const std::string& name) const {
  for (std::size_t c = 0; c < header.size(); ++c) {
    if (header[c] == name) return c;
  }
  throw Malformed("line 1: expected a column '" + name + "' in the header, got none");
}

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

}  // namespace limber::report
