#include "results/stress_reader.h"

#include <algorithm>
#include <limits>

#include "results/h5_reader.h"
#include "results/results_layout.h"

namespace limber::results {

Eigen::Index StressTrack::row_at(double t) const {
  if (time.size() == 0) return -1;
  const auto after = std::upper_bound(time.data(), time.data() + time.size(), t);
  return std::max<Eigen::Index>(0, (after - time.data()) - 1);
}

Eigen::VectorXd StressTrack::element_values(Eigen::Index row, int element_count) const {
  Eigen::VectorXd values = Eigen::VectorXd::Constant(element_count, std::numeric_limits<double>::quiet_NaN());
  if (row < 0 || row >= equivalent.rows()) return values;
  for (std::size_t k = 0; k < elements.size(); ++k) {
    if (elements[k] < element_count) values(elements[k]) = equivalent(row, static_cast<Eigen::Index>(k));
  }
  return values;
}

std::vector<std::optional<StressTrack>> read_stress_tracks(const Results& results) {
  const H5Reader r(results.file, "results file", " (run `limber run` first)");
  std::vector<std::optional<StressTrack>> tracks;
  const auto ns = static_cast<hsize_t>(results.sample_count());
  for (const BodyTrack& body : results.bodies) {
    const std::string g = layout::at(body.group, layout::body::kStress);
    const std::string peak_path = layout::at(g, layout::stress::kPeak);
    const std::string peak_element_path = layout::at(g, layout::stress::kPeakElement);
    const std::string elements_path = layout::at(g, layout::stress::kElements);
    const std::string time_path = layout::at(g, layout::stress::kTime);
    const std::string equivalent_path = layout::at(g, layout::stress::kEquivalent);
    if (!r.exists(g)) {
      tracks.emplace_back();
      continue;
    }
    StressTrack track;
    // Peak at every sample, cut to the samples every other series holds.
    const hsize_t n_peak = std::min({ns, r.rows(peak_path, 0), r.rows(peak_element_path, 0)});
    const std::vector<double> peak = r.read<double>(peak_path, H5T_NATIVE_DOUBLE, n_peak);
    const std::vector<int> element = r.read<int>(peak_element_path, H5T_NATIVE_INT, n_peak);
    track.peak = Eigen::Map<const Eigen::VectorXd>(peak.data(), static_cast<Eigen::Index>(n_peak));
    track.peak_element = Eigen::Map<const Eigen::VectorXi>(element.data(), static_cast<Eigen::Index>(n_peak));
    // History: the rows complete in both datasets.
    const hsize_t ne = r.rows(elements_path, 0);
    track.elements = r.read<int>(elements_path, H5T_NATIVE_INT, ne);
    const int count = static_cast<int>(body.mesh.lines.rows() + body.mesh.quads.rows());
    if (std::any_of(track.elements.begin(), track.elements.end(), [&](int e) { return e < 0 || e >= count; })) {
      r.fail("element numbers in 0.." + std::to_string(count - 1) + " in " + elements_path, "others");
    }
    const hsize_t rows = std::min(r.rows(time_path, 0), r.rows(equivalent_path, ne));
    const std::vector<double> time = r.read<double>(time_path, H5T_NATIVE_DOUBLE, rows);
    const std::vector<double> equivalent = r.read<double>(equivalent_path, H5T_NATIVE_DOUBLE, rows);
    track.time = Eigen::Map<const Eigen::VectorXd>(time.data(), static_cast<Eigen::Index>(rows));
    track.equivalent = Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(
        equivalent.data(), static_cast<Eigen::Index>(rows), static_cast<Eigen::Index>(ne));
    // No history row beyond the last complete sample.
    if (ns > 0) {
      const double last = results.time(static_cast<Eigen::Index>(ns) - 1);
      Eigen::Index keep = 0;
      while (keep < track.time.size() && track.time(keep) <= last) ++keep;
      track.time.conservativeResize(keep);
      track.equivalent.conservativeResize(keep, Eigen::NoChange);
    }
    tracks.push_back(std::move(track));
  }
  return tracks;
}

}  // namespace limber::results
