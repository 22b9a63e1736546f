#include "sweep/work_precision.h"

#include <cmath>
#include <fstream>
#include <sstream>

#include <fmt/format.h>

#include "core/error.h"
#include "select/selection_files.h"
#include "select/series_error.h"
#include "core/json_text.h"
#include "run/run_record.h"
#include "sweep/flat_json.h"
#include "results/file_names.h"
#include "results/results_layout.h"

namespace limber::sweep {

namespace {

using select::csv_field;

std::string read_text(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

std::ofstream open_for_writing(const std::filesystem::path& file) {
  std::filesystem::create_directories(file.parent_path());
  std::ofstream out(file, std::ios::binary);
  if (!out) throw InputError("expected a writable file, got '" + file.string() + "'");
  return out;
}

std::string number(double value) { return std::isfinite(value) ? fmt::format("{:.9g}", value) : ""; }
std::string optional_number(const std::optional<double>& value) { return value ? number(*value) : ""; }

// The last line of a child's stderr that says what went wrong ("limber: error: ...").
std::string error_line(const std::filesystem::path& log) {
  std::istringstream lines(read_text(log));
  std::string line, last;
  while (std::getline(lines, line)) {
    if (line.find("error") != std::string::npos) last = line;
  }
  return last;
}

}  // namespace

void write_process_record(const std::filesystem::path& point_directory, const ChildOutcome& outcome) {
  std::filesystem::create_directories(point_directory);
  std::ofstream(point_directory / results::kProcessJsonFileName, std::ios::binary)
      << fmt::format("{{\"exit_code\": {}, \"signal\": {}, \"process_s\": {}, \"peak_rss_kib\": {}, "
                     "\"spawn_error\": {}}}\n",
                     outcome.exit_code, outcome.signal, json_number(outcome.wall_seconds), outcome.peak_rss_kib,
                     json_string(outcome.spawn_error));
}

bool point_finished(const std::filesystem::path& point_directory) {
  const std::string process = read_text(point_directory / results::kProcessJsonFileName);
  if (process.empty()) return false;
  // Refused as bad input (exit 1): the same setting is refused again.
  if (json_number_field(process, "exit_code") == 1.0) return true;
  return final_status(read_run_status(point_directory / results::kResultsFileName));
}

SweepRow read_row(const SweepPoint& point, const std::filesystem::path& point_directory,
                  const RunSeries& reference, const std::vector<std::string>& quantities) {
  SweepRow row;
  row.point = point;
  const std::string process = read_text(point_directory / results::kProcessJsonFileName);
  if (process.empty()) {
    row.status = kNotRun;
    return row;
  }
  row.exit_code = static_cast<int>(json_number_field(process, "exit_code").value_or(-1));
  row.signal = static_cast<int>(json_number_field(process, "signal").value_or(0));
  row.process_s = json_number_field(process, "process_s").value_or(kNaN);
  row.peak_rss_mib = json_number_field(process, "peak_rss_kib").value_or(kNaN) / 1024.0;
  const std::string spawn_error = json_string_field(process, "spawn_error").value_or("");

  // The child's run record (run/run_record.h); its status is that of results.h5. A record cut
  // short by a crash counts as none.
  const std::string report = read_text(point_directory / results::kRunJsonFileName);
  run::RunRecord record;
  try {
    if (!report.empty()) record = run::read_run_record(report);
  } catch (const InputError&) {
    record = {};
  }
  row.status = record.status;
  row.message = record.message;
  row.wall_s = record.wall_s;
  row.steps = record.steps;
  row.rejected_steps = record.rejected_steps;
  row.newton_iterations = record.newton_iterations;
  row.jacobian_evaluations = record.jacobian_evaluations;
  row.residual_evaluations = record.residual_evaluations;
  row.energy_relative = record.energy_relative;
  row.local_error = record.local_error;
  row.drift_relative = record.drift_relative;

  // No report: the child ended on bad input (exit 1), a signal, or never started.
  if (row.status.empty()) {
    const std::string file_status = read_run_status(point_directory / results::kResultsFileName);
    row.status = file_status == results::layout::status::kInterrupted || row.exit_code == 4 ? results::layout::status::kInterrupted
                 : row.exit_code == 1 && row.signal == 0 ? results::layout::status::kFailed
                                                         : kCrashed;
    row.message = !spawn_error.empty() ? spawn_error
                  : row.signal != 0    ? fmt::format("killed by signal {} ({})", row.signal, strsignal(row.signal))
                                       : error_line(point_directory / results::kRunLogFileName);
    if (row.message.empty()) row.message = fmt::format("exit status {} without a report", row.exit_code);
    return row;
  }
  if (!row.finished()) return row;

  // Errors against the reference, per quantity, on the reference's samples.
  RunSeries run;
  try {
    run = read_run_series(point_directory / results::kResultsFileName);
  } catch (const InputError& error) {
    row.status = kCrashed;
    row.message = error.what();
    return row;
  }
  row.f_max_hz = run.f_max_hz;
  if (point.step && run.f_max_hz > 0.0) row.steps_per_period = 1.0 / (*point.step * run.f_max_hz);
  row.error_peak = row.error_rms = 0.0;
  double worst = -1.0;
  for (const std::string& quantity : quantities) {
    const int column = quantity_column(run, quantity);
    const int reference_column = quantity_column(reference, quantity);
    QuantityError error{quantity};
    if (column >= 0 && reference_column >= 0) {
      const select::SeriesError e = select::series_error(run.time, run.values.col(column), reference.time,
                                                         reference.values.col(reference_column));
      error.peak = e.peak;
      error.rms = e.rms;
    }
    row.errors.push_back(error);
    // A quantity the run lacks makes its error unknown, never small.
    if (std::isnan(error.peak)) {
      row.error_peak = row.error_rms = kNaN;
      row.worst_quantity = quantity + " (not compared)";
      worst = std::numeric_limits<double>::infinity();
      continue;
    }
    row.error_peak = std::max(row.error_peak, error.peak);
    row.error_rms = std::max(row.error_rms, error.rms);
    if (std::max(error.peak, error.rms) > worst) {
      worst = std::max(error.peak, error.rms);
      row.worst_quantity = quantity;
    }
  }
  return row;
}

std::optional<std::size_t> cheapest_meeting(const std::vector<SweepRow>& rows, double target, bool rms) {
  std::optional<std::size_t> chosen;
  for (std::size_t k = 0; k < rows.size(); ++k) {
    const SweepRow& row = rows[k];
    // Only a point whose own accuracy check passed (never ok_inaccurate).
    if (row.status != results::layout::status::kOk || !(row.error(rms) <= target) || !std::isfinite(row.wall_s)) continue;
    if (!chosen || row.wall_s < rows[*chosen].wall_s) chosen = k;
  }
  return chosen;
}

void write_table_csv(const std::filesystem::path& file, const std::vector<SweepRow>& rows,
                     std::optional<std::size_t> chosen) {
  std::ofstream out = open_for_writing(file);
  out << "point,curve,integrator,rtol,step,modes,status,message,exit_code,wall_s,process_s,steps,rejected_steps,"
         "newton_iterations,jacobian_evaluations,residual_evaluations,peak_rss_mib,energy_relative,local_error,"
         "drift_relative,error_peak,error_rms,worst_quantity,resumed,rank,role,f_max_hz,steps_per_period\n";
  for (std::size_t k = 0; k < rows.size(); ++k) {
    const SweepRow& r = rows[k];
    out << csv_field(r.point.name()) << ',' << csv_field(r.point.curve()) << ',' << r.point.integrator << ','
        << optional_number(r.point.rtol) << ',' << optional_number(r.point.step) << ','
        << (r.point.modes ? std::to_string(*r.point.modes) : "") << ',' << r.status << ',' << csv_field(r.message)
        << ',' << r.exit_code << ',' << number(r.wall_s) << ',' << number(r.process_s) << ',' << r.steps << ','
        << r.rejected_steps << ',' << r.newton_iterations << ',' << r.jacobian_evaluations << ','
        << r.residual_evaluations << ',' << number(r.peak_rss_mib) << ',' << number(r.energy_relative) << ','
        << number(r.local_error) << ',' << number(r.drift_relative) << ',' << number(r.error_peak) << ','
        << number(r.error_rms) << ',' << csv_field(r.worst_quantity) << ',' << (r.resumed ? 1 : 0) << ','
        << r.rank << ',' << (chosen && *chosen == k ? "chosen" : "") << ',' << number(r.f_max_hz) << ','
        << number(r.steps_per_period) << '\n';
  }
  out.close();
  if (!out) throw std::runtime_error("cannot write '" + file.string() + "'");
}

void write_errors_csv(const std::filesystem::path& file, const std::vector<SweepRow>& rows) {
  std::ofstream out = open_for_writing(file);
  out << "point,quantity,error_peak,error_rms\n";
  for (const SweepRow& r : rows) {
    for (const QuantityError& e : r.errors) {
      out << csv_field(r.point.name()) << ',' << csv_field(e.quantity) << ',' << number(e.peak) << ','
          << number(e.rms) << '\n';
    }
  }
  out.close();
  if (!out) throw std::runtime_error("cannot write '" + file.string() + "'");
}

std::string row_json(const SweepRow& row) {
  const std::string array = rows_json({row}, std::nullopt);
  return array.substr(1, array.size() - 2);
}

SweepRow row_from_json(const std::string& object) {
  SweepRow row;
  const auto number = [&](const char* key) { return json_number_field(object, key); };
  const auto text = [&](const char* key) { return json_string_field(object, key).value_or(""); };
  const auto count = [&](const char* key) { return static_cast<long>(number(key).value_or(0)); };
  row.point.integrator = text("integrator");
  row.point.rtol = number("rtol");
  row.point.step = number("step");
  if (const auto modes = number("modes")) row.point.modes = static_cast<int>(*modes);
  row.status = text("status");
  row.message = text("message");
  row.exit_code = static_cast<int>(number("exit_code").value_or(-1));
  row.wall_s = number("wall_s").value_or(kNaN);
  row.process_s = number("process_s").value_or(kNaN);
  row.steps = count("steps");
  row.rejected_steps = count("rejected_steps");
  row.newton_iterations = count("newton_iterations");
  row.jacobian_evaluations = count("jacobian_evaluations");
  row.residual_evaluations = count("residual_evaluations");
  row.peak_rss_mib = number("peak_rss_mib").value_or(kNaN);
  row.energy_relative = number("energy_relative").value_or(kNaN);
  row.local_error = number("local_error").value_or(kNaN);
  row.drift_relative = number("drift_relative").value_or(kNaN);
  row.error_peak = number("error_peak").value_or(kNaN);
  row.error_rms = number("error_rms").value_or(kNaN);
  row.worst_quantity = text("worst_quantity");
  row.f_max_hz = number("f_max_hz").value_or(kNaN);
  row.steps_per_period = number("steps_per_period").value_or(kNaN);
  row.resumed = object.find("\"resumed\": true") != std::string::npos;
  row.rank = static_cast<int>(number("rank").value_or(0));
  // "errors": [{"quantity": ..., "peak": ..., "rms": ...}, ...] up to the key after it.
  const std::string marker = "{\"quantity\": ";
  const std::size_t begin = object.find("\"errors\": [");
  const std::size_t end = object.find(", \"resumed\": ", begin);
  std::size_t at = object.find(marker, begin);
  while (begin != std::string::npos && at != std::string::npos && at < end) {
    const std::size_t next = std::min(object.find(marker, at + 1), end);
    const std::string item = object.substr(at, next - at);
    row.errors.push_back({json_string_field(item, "quantity").value_or(""),
                          json_number_field(item, "peak").value_or(kNaN),
                          json_number_field(item, "rms").value_or(kNaN)});
    at = next == end ? std::string::npos : next;
  }
  return row;
}

std::string rows_json(const std::vector<SweepRow>& rows, std::optional<std::size_t> chosen) {
  const auto optional_value = [](const std::optional<double>& v) { return v ? json_number(*v) : std::string("null"); };
  std::string text = "[";
  for (std::size_t k = 0; k < rows.size(); ++k) {
    const SweepRow& r = rows[k];
    std::string errors = "[";
    for (std::size_t q = 0; q < r.errors.size(); ++q) {
      errors += fmt::format("{}{{\"quantity\": {}, \"peak\": {}, \"rms\": {}}}", q ? ", " : "",
                            json_string(r.errors[q].quantity), json_number(r.errors[q].peak), json_number(r.errors[q].rms));
    }
    errors += "]";
    text += fmt::format(
        "{}{{\"point\": {}, \"curve\": {}, \"integrator\": {}, \"rtol\": {}, \"step\": {}, \"modes\": {}, "
        "\"status\": {}, \"message\": {}, \"exit_code\": {}, \"wall_s\": {}, \"process_s\": {}, \"steps\": {}, "
        "\"rejected_steps\": {}, \"newton_iterations\": {}, \"jacobian_evaluations\": {}, "
        "\"residual_evaluations\": {}, \"peak_rss_mib\": {}, \"energy_relative\": {}, \"local_error\": {}, "
        "\"drift_relative\": {}, \"error_peak\": {}, \"error_rms\": {}, \"worst_quantity\": {}, \"errors\": {}, "
        "\"resumed\": {}, \"rank\": {}, \"chosen\": {}, \"f_max_hz\": {}, \"steps_per_period\": {}}}",
        k ? ", " : "", json_string(r.point.name()), json_string(r.point.curve()), json_string(r.point.integrator),
        optional_value(r.point.rtol), optional_value(r.point.step),
        r.point.modes ? std::to_string(*r.point.modes) : "null", json_string(r.status), json_string(r.message),
        r.exit_code, json_number(r.wall_s), json_number(r.process_s), r.steps, r.rejected_steps, r.newton_iterations,
        r.jacobian_evaluations, r.residual_evaluations, json_number(r.peak_rss_mib), json_number(r.energy_relative),
        json_number(r.local_error), json_number(r.drift_relative), json_number(r.error_peak), json_number(r.error_rms),
        json_string(r.worst_quantity), errors, r.resumed ? "true" : "false", r.rank,
        chosen && *chosen == k ? "true" : "false", json_number(r.f_max_hz), json_number(r.steps_per_period));
  }
  return text + "]";
}

bool SweepRow::finished() const {
  return status == results::layout::status::kOk || status == results::layout::status::kInaccurate;
}

}  // namespace limber::sweep
