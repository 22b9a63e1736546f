// System modes as results files that `limber render` draws as it draws a run (docs/linearize.md,
// "Mode shapes in limber render"): for elastic mode k of a linearization, the file
// DIR/system_modes/mode_<kk>/results.h5 (kk its number in linear_modes.csv, from 01) holds one
// period of the mechanism moving in that mode,
//   q(t) = q0 ⊕ (A sin 2π f t) φ_k,   v(t) = A 2π f cos(2π f t) φ_k,   t = 0 … 1/f,
// φ_k the mass-normalized undamped shape (linearization.h), f its undamped frequency, sampled
// at `frames` + 1 instants, every body, flexible ones with their modal coordinates. A scales the
// shape so that the largest displacement of a marker is `amplitude_fraction` of the
// mechanism's size (the diagonal of its markers' bounding box) and no body turns by more than
// kMaxModeRotation. Rigid modes are not written (no period). The files are results.h5 of the
// usual layout (docs/results-format.md, integrator "linear mode"), so render, report and the
// Python module read them unchanged.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "multibody/model.h"
#include "run/linearize_run.h"

namespace limber::run {

inline constexpr double kMaxModeRotation = 0.2;  // [rad]: small enough to read as a small motion

struct SystemModeFileOptions {
  int modes = 6;                     // the first elastic modes written (0: none)
  int frames = 48;                   // samples of one period, plus the closing one
  double amplitude_fraction = 0.05;  // largest marker displacement / the mechanism's size
};

// Writes the files; returns their paths (fewer than options.modes when there are fewer elastic
// modes). Throws InputError when a directory cannot be written.
std::vector<std::filesystem::path> write_system_mode_files(const multibody::Model& model, const LinearizeSummary& summary,
                                                           const std::filesystem::path& directory,
                                                           const std::string& title, const std::string& case_file,
                                                           const SystemModeFileOptions& options = {});

}  // namespace limber::run
