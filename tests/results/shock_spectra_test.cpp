// A run's shock spectra (results/shock_spectra.h): the event windows, the spectra over them and
// their files (results.h5 /shock_spectra, srs_<probe>.csv), read back with the plain HDF5 API.
#include "results/shock_spectra.h"

#include "core/error.h"
#include "h5_test_read.h"
#include "results/results_layout.h"
#include "results/results_writer.h"
#include "results/shock_spectra_file.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>

namespace limber::results {
namespace {

using testing::dataset_dims;
using testing::read_doubles;
using testing::read_string_attribute;

TEST(ShockWindows, StartAtZeroAndAtEachLatchUpToTheNextOrTheWindowLength) {
  // Latches given out of order; L3 lies past the last sample; L4 locks with L2 (within the
  // 1 ms sample interval).
  const std::vector<ShockWindow> windows =
      shock_windows(0.0, 2.0, {{"L2", 0.6}, {"L1", 0.5}, {"L3", 2.5}, {"L4", 0.6005}}, 0.3, 1e-3);
  ASSERT_EQ(windows.size(), 4u);
  EXPECT_EQ(windows[0].name, "whole run");
  EXPECT_DOUBLE_EQ(windows[0].end, 2.0);
  EXPECT_EQ(windows[1].name, "start");
  EXPECT_DOUBLE_EQ(windows[1].end, 0.3);  // the window length
  EXPECT_EQ(windows[2].name, "latch L1");
  EXPECT_DOUBLE_EQ(windows[2].start, 0.5);
  EXPECT_DOUBLE_EQ(windows[2].end, 0.6);  // the next latch
  EXPECT_EQ(windows[3].name, "latch L2, L4");
  EXPECT_DOUBLE_EQ(windows[3].end, 0.9);
  // A window that would pass the last sample ends there; a latch at the start joins it.
  EXPECT_DOUBLE_EQ(shock_windows(0.0, 1.0, {{"L", 0.9}}, 0.3, 1e-3)[2].end, 1.0);
  EXPECT_EQ(shock_windows(0.0, 1.0, {{"L", 0.0}}, 0.3, 1e-3)[1].name, "start, latch L");
}

// A probe at constant 2 g in x, a 5 ms half-sine of 50 g in z from t = 0.5 s (a latch there):
// every spectrum of x is 2 g (static gain 1: shock_spectrum_test); z's whole-run and latch
// windows see the same pulse, so the same spectrum; the start window [0, 0.3] sees nothing.
ShockSpectra constant_and_pulse(const ShockSpectrumSettings& settings) {
  const double dt = 1e-4;
  const Eigen::Index ns = 10001;  // 1 s
  ProbeHistory probe{"tip", {}};
  probe.acceleration.setZero(ns, 3);
  probe.acceleration.col(0).setConstant(2.0 * kStandardGravity);
  Eigen::VectorXd time(ns);
  for (Eigen::Index k = 0; k < ns; ++k) {
    time(k) = static_cast<double>(k) * dt;
    const double s = time(k) - 0.5;
    if (s > 0.0 && s < 0.005) probe.acceleration(k, 2) = 50.0 * kStandardGravity * std::sin(std::numbers::pi * s / 0.005);
  }
  return shock_spectra(time, dt, {probe}, {{"L1", 0.5}}, settings);
}

TEST(ShockSpectra, PerWindowAndAxis) {
  const ShockSpectra spectra = constant_and_pulse({});
  // Default grid: 5 Hz to 1/(10 h) = 1 kHz in 1/6 octaves: 5 · 2^(k/6) ≤ 1000, k ≤ 45.86.
  ASSERT_EQ(spectra.frequency_hz.size(), 46u);
  EXPECT_NEAR(spectra.settings.max_frequency_hz, 5.0 * std::exp2(45.0 / 6.0), 1e-9);
  ASSERT_EQ(spectra.windows.size(), 3u);  // whole run, start, latch L1
  ASSERT_EQ(spectra.probes.size(), 1u);
  const ProbeSpectra& tip = spectra.probes[0];
  for (std::size_t w = 0; w < 3; ++w) {
    EXPECT_NEAR(tip.windows[w][0].maximax.maxCoeff(), 2.0 * kStandardGravity, 1e-9);
    EXPECT_NEAR(tip.windows[w][0].maximax.minCoeff(), 2.0 * kStandardGravity, 1e-9);
    EXPECT_EQ(tip.windows[w][1].maximax.maxCoeff(), 0.0);
  }
  EXPECT_EQ(tip.windows[1][2].maximax.maxCoeff(), 0.0);
  // Whole run and latch window: the same pulse from rest, the residual long enough in both.
  EXPECT_TRUE(tip.windows[0][2].maximax.isApprox(tip.windows[2][2].maximax, 1e-12));
  // The pulse's SRS at Q = 10 peaks above its 50 g (a half-sine's shock amplification, about
  // 1.7 at f τ ≈ 0.8 for Q = 10) and follows it at the top of the band.
  EXPECT_GT(tip.windows[2][2].maximax.maxCoeff(), 1.5 * 50.0 * kStandardGravity);
}

TEST(ShockSpectra, RefusesFrequenciesAboveTheBandTheSamplingSupports) {
  ShockSpectrumSettings settings;
  settings.max_frequency_hz = 2000.0;  // 1/(10 h) = 1 kHz at steps of 0.1 ms
  try {
    constant_and_pulse(settings);
    FAIL() << "expected an InputError";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("at most 1000 Hz"), std::string::npos) << error.what();
    EXPECT_NE(std::string(error.what()).find("5e-05 s"), std::string::npos) << error.what();
  }
}

TEST(ShockSpectra, WrittenToResultsAndCsv) {
  const auto dir = std::filesystem::temp_directory_path() / "limber_results_shock_spectra";
  std::filesystem::remove_all(dir);
  const ShockSpectra spectra = constant_and_pulse({});
  {
    ResultsWriter writer(dir, "srs", "case.yaml");
    EXPECT_EQ(writer.add_acceleration_probe({"tip", "panel", 12, Eigen::Vector3d(0.0, 1.0, 0.0)}), 0);
    for (int k = 0; k < 3; ++k) {
      Sample sample;
      sample.time = 0.1 * k;
      sample.probe_accelerations.push_back(Eigen::Vector3d(k, 2.0 * k, 3.0 * k));
      writer.append_sample(sample);
    }
    writer.set_shock_spectra(spectra);
    writer.finish(RunStatus::kOk);
  }
  const hid_t file = H5Fopen((dir / kResultsFileName).c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(file, 0);
  // The probe's history, its attributes.
  const std::string probe = layout::at(layout::kAccelerationProbes, "tip");
  EXPECT_EQ(read_string_attribute(file, probe, layout::acceleration_probe::kBodyAttribute), "panel");
  const std::vector<double> a = read_doubles(file, layout::at(probe, layout::acceleration_probe::kAcceleration));
  ASSERT_EQ(a.size(), 9u);
  EXPECT_EQ(a[7], 4.0);  // sample 2, y
  // The spectra: grid, windows, [nw, 3, nf] per probe.
  namespace srs = layout::shock_spectra;
  EXPECT_EQ(read_doubles(file, layout::at(layout::kShockSpectra, srs::kFrequency)), spectra.frequency_hz);
  const std::string tip = layout::at(layout::at(layout::kShockSpectra, srs::kProbes), "tip");
  const std::vector<hsize_t> dims = dataset_dims(file, layout::at(tip, srs::kMaximax));
  ASSERT_EQ(dims, (std::vector<hsize_t>{3, 3, spectra.frequency_hz.size()}));
  const std::vector<double> maximax = read_doubles(file, layout::at(tip, srs::kMaximax));
  const std::size_t nf = spectra.frequency_hz.size();
  EXPECT_EQ(maximax[(2 * 3 + 2) * nf + 10], spectra.probes[0].windows[2][2].maximax(10));  // latch window, z
  H5Fclose(file);

  // CSV: a header, then windows x frequencies rows; 2 g in x throughout.
  write_shock_spectra_csv(dir, spectra);
  std::ifstream csv(dir / shock_spectrum_csv_name("tip"));
  std::string line;
  std::getline(csv, line);
  EXPECT_EQ(line, "window,window_start_s,window_end_s,frequency_hz,x_m_s2,y_m_s2,z_m_s2,x_g,y_g,z_g");
  std::size_t rows = 0;
  while (std::getline(csv, line)) {
    if (rows++ == 0) {
      EXPECT_EQ(line.substr(0, 16), "whole run,0,1,5,");
    }
    EXPECT_NE(line.find(",2,0,"), std::string::npos) << line;  // x_g = 2, y_g = 0
  }
  EXPECT_EQ(rows, 3 * nf);
}

}  // namespace
}  // namespace limber::results
