// Reads a modes.h5 written by `limber modes` (docs/modes-format.md) for the mode-shape
// animations: each body's mesh and the translations, frequencies, kinds and labels of its
// modes. Like results_reader, through limber_results' reader (results/h5_reader.h): no solver
// classes.
#pragma once

#include "results_reader.h"

#include <filesystem>
#include <string>
#include <vector>

namespace limber::render {

struct BodyModeShapes {
  std::string name;
  FlexibleMesh mesh;                // mode_translations (3 nn) x nm, frequencies_hz nm
  std::vector<std::string> kinds;   // nm: normal | constraint | attachment
  std::vector<std::string> labels;  // nm: e.g. "normal 3"
};

struct ModeShapes {
  std::filesystem::path file;
  std::string title;                   // case title
  std::vector<BodyModeShapes> bodies;  // case-file order (/body_names)
};

// Reads `modes_file`. Throws InputError (expected/got, naming the file) when it is missing,
// not HDF5, not a limber modes file, or lacks a dataset.
ModeShapes read_mode_shapes(const std::filesystem::path& modes_file);

}  // namespace limber::render
