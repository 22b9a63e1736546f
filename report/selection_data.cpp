#include "selection_data.h"

#include "csv_table.h"
#include "results/file_names.h"

#include <map>

namespace limber::report {
namespace {

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
  const std::string shown = std::string(results::kSelectionFolder) + "/" + name;
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
  const std::filesystem::path folder = run_directory / results::kSelectionFolder;
  std::error_code error;
  if (!std::filesystem::is_directory(folder, error)) return std::nullopt;
  SelectionData selection;
  selection.directory = folder;
  read_part(folder, results::kRankingFileName, parse_ranking, selection.ranking, notes);
  read_part(folder, results::kComparisonFileName, parse_comparison, selection.comparison, notes);
  read_part(folder, results::kKeySeriesFileName, parse_key_series, selection.key_series, notes);
  return selection;
}

}  // namespace limber::report
