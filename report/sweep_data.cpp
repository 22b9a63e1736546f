#include "sweep_data.h"

#include "csv_table.h"
#include "results/file_names.h"

namespace limber::report {

std::optional<SweepData> read_sweep(const std::filesystem::path& run_directory, std::vector<std::string>& notes) {
  const std::filesystem::path folder = run_directory / results::kSweepFolder;
  std::error_code error;
  if (!std::filesystem::is_directory(folder, error)) return std::nullopt;
  SweepData sweep;
  sweep.directory = folder;
  const std::string shown = std::string(results::kSweepFolder) + "/" + results::kWorkPrecisionFileName;
  if (!std::filesystem::is_regular_file(folder / results::kWorkPrecisionFileName, error)) {
    notes.push_back(shown + " not found: the work-precision section leaves it out.");
    return sweep;
  }
  try {
    const CsvTable t = read_csv(folder / results::kWorkPrecisionFileName);
    const std::size_t point = t.column("point"), curve = t.column("curve"), status = t.column("status"),
                      message = t.column("message"), wall = t.column("wall_s"), rss = t.column("peak_rss_mib"),
                      steps = t.column("steps"), rejected = t.column("rejected_steps"),
                      newton = t.column("newton_iterations"), jacobian = t.column("jacobian_evaluations"),
                      peak = t.column("error_peak"), rms = t.column("error_rms"), worst = t.column("worst_quantity"),
                      role = t.column("role");
    for (std::size_t r = 0; r < t.rows.size(); ++r) {
      const std::vector<std::string>& f = t.rows[r].second;
      sweep.points.push_back({f[point], f[curve], f[status], f[message], number_field(t, r, wall, true),
                              number_field(t, r, rss, true), integer_field(t, r, steps),
                              integer_field(t, r, rejected), integer_field(t, r, newton),
                              integer_field(t, r, jacobian), number_field(t, r, peak, true),
                              number_field(t, r, rms, true), f[worst], f[role]});
    }
  } catch (const Malformed& e) {
    notes.push_back(shown + " not shown: " + e.what() + ".");
    sweep.points.clear();
  }
  return sweep;
}

}  // namespace limber::report
