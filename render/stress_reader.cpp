#include "stress_reader.h"

#include <algorithm>
#include <limits>

#include "h5_reader.h"

namespace limber::render {

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
    const std::string g = body.group + "/stress";
    if (!r.exists(g)) {
      tracks.emplace_back();
      continue;
    }
    StressTrack track;
    // Peak at every sample, cut to the samples every other series holds.
    const hsize_t n_peak = std::min({ns, r.rows(g + "/peak", 0), r.rows(g + "/peak_element", 0)});
    const std::vector<double> peak = r.read<double>(g + "/peak", H5T_NATIVE_DOUBLE, n_peak);
    const std::vector<int> element = r.read<int>(g + "/peak_element", H5T_NATIVE_INT, n_peak);
    track.peak = Eigen::Map<const Eigen::VectorXd>(peak.data(), static_cast<Eigen::Index>(n_peak));
    track.peak_element = Eigen::Map<const Eigen::VectorXi>(element.data(), static_cast<Eigen::Index>(n_peak));
    // History: the rows complete in both datasets.
    const hsize_t ne = r.rows(g + "/elements", 0);
    track.elements = r.read<int>(g + "/elements", H5T_NATIVE_INT, ne);
    const int count = static_cast<int>(body.mesh.lines.rows() + body.mesh.quads.rows());
    if (std::any_of(track.elements.begin(), track.elements.end(), [&](int e) { return e < 0 || e >= count; })) {
      r.fail("element numbers in 0.." + std::to_string(count - 1) + " in " + g + "/elements", "others");
    }
    const hsize_t rows = std::min(r.rows(g + "/time", 0), r.rows(g + "/equivalent", ne));
    const std::vector<double> time = r.read<double>(g + "/time", H5T_NATIVE_DOUBLE, rows);
    const std::vector<double> equivalent = r.read<double>(g + "/equivalent", H5T_NATIVE_DOUBLE, rows);
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

}  // namespace limber::render
