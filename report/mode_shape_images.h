// Pictures of the mode shapes of each flexible body, drawn with render's offscreen scene from
// the mesh and mode translations stored in results.h5.
#pragma once

#include "run_data.h"

#include <filesystem>
#include <string>
#include <vector>

namespace limber::report {

// The lowest this many modes are drawn per component (in stored order), and every static
// (constraint or attachment) mode besides, up to kMaxStaticModeImages of them.
inline constexpr int kMaxModeImages = 6;
inline constexpr int kMaxStaticModeImages = 12;
// Each shape is scaled so its largest nodal translation is this fraction of the mesh's
// bounding-box diagonal: visible, and still small enough to read as a deformation.
inline constexpr double kModeShapeFraction = 0.1;

struct ModeImage {
  std::string body;        // the body, or "component <name>" for bodies sharing one
  int mode = 0;            // 0-based index in the body's mode set
  double frequency_hz = 0.0;
  std::string label;       // a static mode's kind and origin ("attachment uz at node 10001"), else ""
  std::string file;        // PNG file name inside `images`
};

// Draws the first kMaxModeImages modes and the static modes of each distinct component
// (run.mode_tables: the first of the bodies sharing it) (width x height pixels each) at the
// body's pose of the first sample, into `images` as <prefix>mode_<body>_<k>.png.
// Throws std::runtime_error when no offscreen context can be created.
std::vector<ModeImage> draw_mode_shapes(const RunData& run, const std::filesystem::path& images,
                                        const std::string& prefix, int width, int height);

}  // namespace limber::report
