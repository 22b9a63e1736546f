// CSV files the report reads (those `limber select` and `limber sweep` write): UTF-8, a header
// row, comma separated; a field may be wrapped in double quotes, "" inside quotes being one
// quote. Columns are found by their header names; a malformed file throws Malformed with the
// line, what was expected and what was found.
#pragma once

#include <cstddef>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace limber::report {

// A malformed file: the message says where, what was expected and what was found.
struct Malformed : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// A CSV file: its header and its rows, each with its line number.
struct CsvTable {
  std::vector<std::string> header;
  std::vector<std::pair<int, std::vector<std::string>>> rows;

  // Index of a required column (throws Malformed when absent).
  std::size_t column(const std::string& name) const;
};

// Reads `file` (Windows line ends, a byte-order mark and blank lines tolerated).
CsvTable read_csv(const std::filesystem::path& file);

// Field `column` of row `row` as a number; nullopt when empty and `optional`.
std::optional<double> number_field(const CsvTable& table, std::size_t row, std::size_t column, bool optional);
double required_number(const CsvTable& table, std::size_t row, std::size_t column);
long long integer_field(const CsvTable& table, std::size_t row, std::size_t column);
// "0" or "1".
bool flag_field(const CsvTable& table, std::size_t row, std::size_t column);

}  // namespace limber::report
