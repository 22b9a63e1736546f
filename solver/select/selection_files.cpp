#include "select/selection_files.h"

#include <algorithm>
#include <cmath>
#include <fstream>

#include <fmt/format.h>

#include "core/error.h"
#include "select/mode_set_candidates.h"

namespace limber::select {

namespace {

constexpr const char* kAxisNames = "xyz";

std::ofstream open_for_writing(const std::filesystem::path& file) {
  std::filesystem::create_directories(file.parent_path());
  std::ofstream out(file, std::ios::binary);
  if (!out) throw InputError("expected a writable file, got '" + file.string() + "'");
  return out;
}

void close(std::ofstream& out, const std::filesystem::path& file) {
  out.close();
  if (!out) throw std::runtime_error("cannot write '" + file.string() + "'");
}

// A number with full precision, or empty for NaN.
std::string number(double value) { return std::isnan(value) ? "" : fmt::format("{:.9g}", value); }

}  // namespace

std::string csv_field(const std::string& text) {
  if (text.find_first_of(",\"\n\r") == std::string::npos) return text;
  std::string quoted = "\"";
  for (char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}

void write_ranking_csv(const std::filesystem::path& file, const std::vector<RankedComponent>& ranking) {
  std::ofstream out = open_for_writing(file);
  out << "body,joint,node,quantity,axis,peak,rms,relative,kept,indeterminate\n";
  for (const RankedComponent& c : ranking) {
    out << csv_field(c.body) << ',' << csv_field(c.joint) << ',' << c.node_id << ','
        << (c.load == Load::kForce ? "force" : "torque") << ',' << kAxisNames[c.axis] << ','
        << number(c.peak) << ',' << number(c.rms) << ',' << number(c.relative) << ','
        << (c.kept ? 1 : 0) << ',' << (c.indeterminate ? 1 : 0) << '\n';
  }
  close(out, file);
}

void write_comparison_csv(const std::filesystem::path& file, const std::vector<CandidateRun>& runs,
                          std::optional<std::size_t> chosen, const std::filesystem::path& root) {
  std::ofstream out = open_for_writing(file);
  out << "set,description,modes,reduction_s,run_s,status,error_peak,error_rms,worst_quantity,directory,role,"
         "f_max_hz,step,steps_per_period,resolved,error_event,worst_event\n";
  for (std::size_t k = 0; k < runs.size(); ++k) {
    const CandidateRun& run = runs[k];
    const std::string role = run.candidate.reference ? "reference" : (chosen && *chosen == k ? "chosen" : "");
    out << csv_field(run.candidate.name) << ',' << csv_field(run.candidate.description) << ','
        << run.modes << ',' << number(run.reduction_seconds) << ','
        << number(run.summary.wall_seconds) << ','
        << csv_field(run.status()) << ','
        << number(run.error_peak) << ',' << number(run.error_rms) << ','
        << csv_field(run.worst_quantity) << ','
        << csv_field(run.directory.lexically_relative(root).generic_string()) << ',' << role << ','
        << number(run.step.f_max) << ',' << number(run.step.step) << ',' << number(run.step.steps_per_period) << ','
        << (run.step.resolved ? 1 : 0) << ',' << number(run.peaks.error) << ',' << csv_field(run.peaks.worst) << '\n';
  }
  close(out, file);
}

void write_key_series_csv(const std::filesystem::path& file, const std::vector<CandidateRun>& runs,
                          const std::vector<KeyQuantity>& keys) {
  std::vector<const CandidateRun*> finished;
  Eigen::Index samples = -1;
  for (const CandidateRun& run : runs) {
    if (!run.ok()) continue;
    finished.push_back(&run);
    samples = samples < 0 ? run.time.size() : std::min(samples, run.time.size());
  }
  std::ofstream out = open_for_writing(file);
  out << "time";
  for (const CandidateRun* run : finished) {
    for (const KeyQuantity& key : keys) out << ',' << csv_field(run->candidate.name + "|" + key.name);
  }
  out << '\n';
  std::vector<std::vector<Eigen::VectorXd>> columns;
  for (const CandidateRun* run : finished) {
    std::vector<Eigen::VectorXd> series;
    for (const KeyQuantity& key : keys) series.push_back(key_series(*run, key));
    columns.push_back(std::move(series));
  }
  for (Eigen::Index i = 0; i < samples; ++i) {
    out << number(finished.front()->time(i));
    for (const auto& series : columns) {
      for (const Eigen::VectorXd& values : series) out << ',' << number(values(i));
    }
    out << '\n';
  }
  close(out, file);
}

void write_peaks_csv(const std::filesystem::path& file, const std::vector<CandidateRun>& runs) {
  std::ofstream out = open_for_writing(file);
  out << "set,window,joint,start,reference_start,force,reference_force,force_error,force_time,reference_force_time,"
         "torque,reference_torque,torque_error\n";
  const auto reference = std::find_if(runs.begin(), runs.end(), [](const CandidateRun& r) { return r.candidate.reference; });
  for (const CandidateRun& run : runs) {
    if (!run.ok() || reference == runs.end()) continue;
    // The reference against itself lists its own peaks (differences 0).
    const PeakComparison peaks =
        run.candidate.reference ? compare_peaks(run.summary.peaks, run.summary.peaks) : run.peaks;
    for (const PeakDifference& r : peaks.rows) {
      out << csv_field(run.candidate.name) << ',' << csv_field(r.window) << ',' << csv_field(r.joint) << ','
          << number(r.start) << ',' << number(r.reference_start) << ',' << number(r.force) << ','
          << number(r.reference_force) << ',' << number(r.force_error) << ',' << number(r.force_time) << ','
          << number(r.reference_force_time) << ',' << number(r.torque) << ',' << number(r.reference_torque) << ','
          << number(r.torque_error) << '\n';
    }
  }
  close(out, file);
}

std::string selected_modes_yaml(const CandidateRun& chosen, const std::string& why) {
  std::string text = fmt::format(
      "# limber select: mode set '{}' ({}), {} modes in all.\n# {}\n"
      "# Paste each body's 'modes' into the case's flexible_bodies entry of that name.\n"
      "flexible_bodies:\n",
      chosen.candidate.name, chosen.candidate.description, chosen.modes, why);
  for (const auto& [name, request] : chosen.candidate.requests) {
    std::vector<int> ids;
    for (const io::FlexibleBodyCase& body : chosen.input->flexible_bodies) {
      if (body.name == name) ids = body.model.node_ids;
    }
    text += "  " + name + ":\n    modes:\n";
    const std::string modes = modes_yaml(request, ids);
    std::size_t start = 0;
    while (start < modes.size()) {
      const std::size_t end = modes.find('\n', start);
      text += "      " + modes.substr(start, end - start) + "\n";
      start = end + 1;
    }
  }
  return text;
}

}  // namespace limber::select
