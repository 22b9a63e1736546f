#include "results/probe_reader.h"

#include "results/h5_reader.h"
#include "results/link_name.h"
#include "results/results_layout.h"

namespace limber::results {

namespace {

namespace srs = layout::shock_spectra;

double double_attribute(const H5Reader& file, const std::string& object, const char* name) {
  return file.doubles_attribute(object, name, 1)[0];
}

}  // namespace

std::vector<AccelerationProbeTrack> read_acceleration_probes(const H5Reader& file) {
  std::vector<AccelerationProbeTrack> probes;
  for (const std::string& link : file.members(layout::kAccelerationProbes)) {
    const std::string group = layout::at(layout::kAccelerationProbes, link);
    const std::string path = layout::at(group, layout::acceleration_probe::kAcceleration);
    AccelerationProbeTrack probe;
    probe.name = file.string_attribute(group, kNameAttribute, false, link);
    probe.body = file.string_attribute(group, layout::acceleration_probe::kBodyAttribute, false);
    for (const auto& [key, value] : file.attribute_texts(group)) {
      if (key == layout::acceleration_probe::kNodeAttribute) probe.node = std::stoi(value);
    }
    const hsize_t rows = file.rows(path, 3);
    const std::vector<double> values = file.read<double>(path, H5T_NATIVE_DOUBLE, rows);
    probe.acceleration = Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>>(
        values.data(), static_cast<Eigen::Index>(rows), 3);
    probes.push_back(std::move(probe));
  }
  return probes;
}

std::optional<ShockSpectraData> read_shock_spectra(const H5Reader& file) {
  if (!file.exists(layout::kShockSpectra)) return std::nullopt;
  const std::string g = layout::kShockSpectra;
  ShockSpectraData data;
  data.q = double_attribute(file, g, srs::kQAttribute);
  data.window_length = double_attribute(file, g, srs::kWindowLengthAttribute);
  if (file.has_attribute(g, srs::kLongestStepAttribute)) {
    data.longest_step = double_attribute(file, g, srs::kLongestStepAttribute);
  }
  // Grid and windows.
  const std::string frequency = layout::at(g, srs::kFrequency);
  const hsize_t nf = file.rows(frequency, 0);
  const std::vector<double> f = file.read<double>(frequency, H5T_NATIVE_DOUBLE, nf);
  data.frequency_hz = Eigen::Map<const Eigen::VectorXd>(f.data(), static_cast<Eigen::Index>(nf));
  data.window_names = file.strings(layout::at(g, srs::kWindowName));
  const hsize_t nw = data.window_names.size();
  for (auto [name, target] : {std::pair{srs::kWindowStart, &data.window_start}, std::pair{srs::kWindowEnd, &data.window_end}}) {
    const std::string path = layout::at(g, name);
    if (file.rows(path, 0) != nw) file.fail(std::to_string(nw) + " rows in " + path, std::to_string(file.rows(path, 0)));
    *target = file.read<double>(path, H5T_NATIVE_DOUBLE, nw);
  }
  // Per probe: maximax [nw, 3, nf].
  const std::string probes = layout::at(g, srs::kProbes);
  for (const std::string& link : file.members(probes)) {
    const std::string group = layout::at(probes, link);
    const std::string path = layout::at(group, srs::kMaximax);
    if (file.dims(path) != std::vector<hsize_t>{nw, 3, nf}) {
      file.fail("a [" + std::to_string(nw) + ", 3, " + std::to_string(nf) + "] dataset " + path, "another shape");
    }
    const std::vector<double> values = file.read<double>(path, H5T_NATIVE_DOUBLE, nw);
    ProbeSpectrumData probe{file.string_attribute(group, kNameAttribute, false, link), {}};
    for (hsize_t w = 0; w < nw; ++w) {
      std::array<Eigen::VectorXd, 3> axes;
      for (hsize_t a = 0; a < 3; ++a) {
        axes[a] = Eigen::Map<const Eigen::VectorXd>(values.data() + (w * 3 + a) * nf, static_cast<Eigen::Index>(nf));
      }
      probe.maximax.push_back(std::move(axes));
    }
    data.probes.push_back(std::move(probe));
  }
  return data;
}

}  // namespace limber::results
