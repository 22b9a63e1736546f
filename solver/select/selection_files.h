// What `limber select -o DIR` leaves for the user and for `limber report DIR`
// (docs/select.md, "Files"):
//   DIR/selection/ranking.csv     the ranked reaction components (reaction_ranking.h)
//   DIR/selection/comparison.csv  one row per mode set: modes, cost, error, role
//   DIR/selection/key_series.csv  time and every set's key quantities, one column each
//   DIR/selection/event_peaks.csv per set, window and joint: its event peaks and the reference's
//   DIR/selected_modes.yaml       the chosen set as `modes` entries to paste into the case
// CSV: a header row, comma separated; text fields with a comma or a quote are quoted.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "select/reaction_ranking.h"
#include "select/selection_study.h"

namespace limber::select {

void write_ranking_csv(const std::filesystem::path& file, const std::vector<RankedComponent>& ranking);

// `root` is DIR: directories are written relative to it. `chosen` indexes `runs`.
void write_comparison_csv(const std::filesystem::path& file, const std::vector<CandidateRun>& runs,
                          std::optional<std::size_t> chosen, const std::filesystem::path& root);

// Finished runs only, on the samples all of them have.
void write_key_series_csv(const std::filesystem::path& file, const std::vector<CandidateRun>& runs,
                          const std::vector<KeyQuantity>& keys);

// One row per set (the reference's own rows included), window and joint: the peaks of force and
// torque, the reference's and their relative differences (peak_comparison.h).
void write_peaks_csv(const std::filesystem::path& file, const std::vector<CandidateRun>& runs);

// The chosen run's mode requests, one `modes` block per flexible_bodies entry, with a header
// saying what was chosen and why.
std::string selected_modes_yaml(const CandidateRun& chosen, const std::string& why);

// Text field for CSV: quoted when it holds a comma, a quote or a line break.
std::string csv_field(const std::string& text);

}  // namespace limber::select
