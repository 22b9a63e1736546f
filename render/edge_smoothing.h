// Anti-aliasing of a finished frame on the CPU: fast approximate anti-aliasing (FXAA) after
// T. Lottes, "FXAA", NVIDIA white paper, 2009 (the algorithm of its version 3.11, which VTK's
// OpenGL pass also follows). In llvmpipe VTK's pass costs about 40 ms of CPU per 1280 x 720
// frame, even with thresholds that let every pixel exit early; this pass does the edge work
// only for the pixels on edges and costs about 2 ms (docs/benchmarks.md).
#pragma once

#include "image.h"

#include <vector>

namespace limber::render {

// Thresholds of the edge test and the subpixel blend, as fractions of full luma (0..1).
// Defaults: VTK's vtkFXAAOptions defaults (relative 1/8, hard 1/16, subpixel limit 3/4,
// 12 search steps each way).
struct EdgeSmoothingOptions {
  double relative_contrast = 1.0 / 8.0;  // skip pixels whose luma range < this x their max luma
  double hard_contrast = 1.0 / 16.0;     // ... or < this (absolute)
  double subpixel_limit = 0.75;          // largest blend of a pixel towards its neighbour
  int search_steps = 12;                 // pixels searched each way for an edge's ends
};

// Smooths the aliased edges of `image` in place: each pixel on an edge is blended with its
// neighbour across the edge by the fraction FXAA derives from its distance to the nearer end
// of the edge (and from subpixel contrast). Pixels inside any of `keep` (texts, which FreeType
// has anti-aliased already, and the colour bar) and the outermost rows and columns are left as
// they are. Precondition (DEMAND): image.rgb.size() == 3 * width * height.
void smooth_edges(Image& image, const std::vector<PixelBox>& keep = {},
                  const EdgeSmoothingOptions& options = {});

}  // namespace limber::render
