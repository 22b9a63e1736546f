#include "results/shock_spectra_file.h"

#include <cstdio>
#include <fstream>
#include <vector>

#include "core/error.h"
#include "results/h5_handle.h"
#include "results/h5_write.h"
#include "results/link_name.h"
#include "results/results_layout.h"

namespace limber::results {

namespace {

namespace layout_srs = layout::shock_spectra;

bool write_double_attribute(hid_t object, const char* name, double value) {
  return try_write_scalar_attribute(object, name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, &value);
}

// One of maximax, primary, residual as [nw, 3, nf], row-major.
std::vector<double> stacked(const ProbeSpectra& probe, std::size_t nf,
                            Eigen::VectorXd ShockSpectrum::*member) {
  std::vector<double> values;
  values.reserve(probe.windows.size() * 3 * nf);
  for (const std::array<ShockSpectrum, 3>& window : probe.windows) {
    for (const ShockSpectrum& axis : window) values.insert(values.end(), (axis.*member).data(), (axis.*member).data() + nf);
  }
  return values;
}

// A CSV number: shortest round-trip text.
std::string number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.9g", value);
  return text;
}

// A CSV field: quoted when it holds a comma, a quote or a line break.
std::string field(const std::string& text) {
  if (text.find_first_of(",\"\n\r") == std::string::npos) return text;
  std::string quoted = "\"";
  for (const char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}

}  // namespace

bool try_write_shock_spectra(hid_t file, const ShockSpectra& spectra) {
  const H5Handle group(H5Gcreate2(file, layout::kShockSpectra, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT));
  if (!group.valid()) return false;
  const hid_t g = group.get();
  // Settings, grid and windows.
  const ShockSpectrumSettings& s = spectra.settings;
  bool ok = write_double_attribute(g, layout_srs::kQAttribute, s.q) &&
            write_double_attribute(g, layout_srs::kWindowLengthAttribute, s.window_seconds) &&
            write_double_attribute(g, layout_srs::kMinFrequencyAttribute, s.min_frequency_hz) &&
            write_double_attribute(g, layout_srs::kMaxFrequencyAttribute, s.max_frequency_hz) &&
            write_double_attribute(g, layout_srs::kLongestStepAttribute, spectra.longest_step);
  const hsize_t nf = spectra.frequency_hz.size(), nw = spectra.windows.size();
  std::vector<std::string> names;
  std::vector<double> starts, ends;
  for (const ShockWindow& w : spectra.windows) {
    names.push_back(w.name);
    starts.push_back(w.start);
    ends.push_back(w.end);
  }
  ok = ok &&
       try_write_dataset(g, layout_srs::kFrequency, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, {nf}, spectra.frequency_hz.data()) &&
       try_write_string_dataset(g, layout_srs::kWindowName, names) &&
       try_write_dataset(g, layout_srs::kWindowStart, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, {nw}, starts.data()) &&
       try_write_dataset(g, layout_srs::kWindowEnd, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, {nw}, ends.data());
  if (!ok) return false;
  // Per probe: maximax, primary and residual [nw, 3, nf].
  const H5Handle probes(H5Gcreate2(g, layout_srs::kProbes, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT));
  if (!probes.valid()) return false;
  for (const ProbeSpectra& probe : spectra.probes) {
    const H5Handle p(H5Gcreate2(probes.get(), link_name(probe.probe).c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT));
    if (!p.valid() || !try_write_string_attribute(p.get(), kNameAttribute, probe.probe)) return false;
    for (const auto& [name, member] : {std::pair{layout_srs::kMaximax, &ShockSpectrum::maximax},
                                       std::pair{layout_srs::kPrimary, &ShockSpectrum::primary},
                                       std::pair{layout_srs::kResidual, &ShockSpectrum::residual}}) {
      const std::vector<double> values = stacked(probe, nf, member);
      if (!try_write_dataset(p.get(), name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, {nw, 3, nf}, values.data())) return false;
    }
  }
  return true;
}

std::string shock_spectrum_csv_name(const std::string& probe) { return "srs_" + link_name(probe) + ".csv"; }

void write_shock_spectra_csv(const std::filesystem::path& directory, const ShockSpectra& spectra) {
  for (const ProbeSpectra& probe : spectra.probes) {
    const std::filesystem::path path = directory / shock_spectrum_csv_name(probe.probe);
    std::ofstream out(path);
    out << "window,window_start_s,window_end_s,frequency_hz,x_m_s2,y_m_s2,z_m_s2,x_g,y_g,z_g\n";
    for (std::size_t w = 0; w < spectra.windows.size(); ++w) {
      const ShockWindow& window = spectra.windows[w];
      for (std::size_t j = 0; j < spectra.frequency_hz.size(); ++j) {
        out << field(window.name) << ',' << number(window.start) << ',' << number(window.end) << ','
            << number(spectra.frequency_hz[j]);
        for (const double scale : {1.0, 1.0 / kStandardGravity}) {
          for (const ShockSpectrum& axis : probe.windows[w]) out << ',' << number(scale * axis.maximax(static_cast<Eigen::Index>(j)));
        }
        out << '\n';
      }
    }
    if (!out) throw InputError("expected a writable file, got a failure writing '" + path.string() + "'");
  }
}

}  // namespace limber::results
