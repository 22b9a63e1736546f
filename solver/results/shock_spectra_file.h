// The files of a run's shock response spectra (shock_spectra.h; docs/results-format.md,
// docs/shock-response-spectrum.md): the group /shock_spectra of results.h5 and one CSV file per
// probe, DIR/srs_<probe>.csv.
#pragma once

#include <hdf5.h>

#include <filesystem>
#include <string>

#include "results/shock_spectra.h"

namespace limber::results {

// Writes /shock_spectra (results_layout.h) into the open file `file`. Returns false on an HDF5
// failure (the caller names the file). Precondition: /shock_spectra does not exist yet.
bool try_write_shock_spectra(hid_t file, const ShockSpectra& spectra);

// The CSV file of one probe: "srs_<link name of the probe>.csv" (results/link_name.h).
std::string shock_spectrum_csv_name(const std::string& probe);

// Writes directory/srs_<probe>.csv for every probe: the header line
//   window,window_start_s,window_end_s,frequency_hz,x_m_s2,y_m_s2,z_m_s2,x_g,y_g,z_g
// then one row per window and frequency (maximax, ground axes; g = 9.80665 m/s²), windows in
// their order, frequencies ascending. Throws InputError naming the file when it cannot be
// written.
void write_shock_spectra_csv(const std::filesystem::path& directory, const ShockSpectra& spectra);

}  // namespace limber::results
