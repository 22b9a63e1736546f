// The typed reader of results.h5, the acceleration probes and their shock response spectra
// (docs/results-format.md, /acceleration_probes and /shock_spectra; the spectra's method:
// docs/shock-response-spectrum.md). run_records.h reads them with the other series.
#pragma once

#include <Eigen/Core>

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace limber::results {

class H5Reader;

// A probe's absolute acceleration, ground axes [m/s²], ns x 3.
struct AccelerationProbeTrack {
  std::string name;
  std::string body;
  int node = -1;  // FE node id on a flexible body, −1 on a rigid one
  Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor> acceleration;
};

// One probe's maximax spectra: per window, per ground axis x, y, z, nf values [m/s²].
struct ProbeSpectrumData {
  std::string name;
  std::vector<std::array<Eigen::VectorXd, 3>> maximax;
};

struct ShockSpectraData {
  double q = 0.0;
  double window_length = 0.0;  // [s]
  // The longest integrator step of the record [s], which sets the band the spectra hold
  // (docs/shock-response-spectrum.md); none in files written before it was stored.
  std::optional<double> longest_step;
  Eigen::VectorXd frequency_hz;
  std::vector<std::string> window_names;  // "whole run", "start", "latch <name>[, <name>...]"
  std::vector<double> window_start, window_end;  // [s]
  std::vector<ProbeSpectrumData> probes;
};

// The probes of the file, in name order; each history has its file's rows (the caller cuts
// them to the complete samples).
std::vector<AccelerationProbeTrack> read_acceleration_probes(const H5Reader& file);

// The spectra, or none when the file has no /shock_spectra (no probes, or the run did not
// write them). A group of another shape is an InputError naming the file.
std::optional<ShockSpectraData> read_shock_spectra(const H5Reader& file);

}  // namespace limber::results
