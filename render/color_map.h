// The colour maps flexible bodies are coloured with (docs/rendering.md). Viridis, the default,
// is perceptually uniform and readable in grey and by colour-blind viewers (Smith & van der
// Walt, "A Better Default Colormap for Matplotlib", SciPy 2015: its CIE L* rises monotonically
// from 0 to 1); the rainbow (HSV hue blue -> red) is the map limber used before, kept selectable
// (`--color-map rainbow`) for comparison with older frames.
#pragma once

#include <array>
#include <string>

class vtkLookupTable;

namespace limber::render {

enum class ColorMap { kViridis, kRainbow };

// Parses "viridis" or "rainbow"; throws InputError (expected/got) otherwise.
ColorMap parse_color_map(const std::string& text);

// RGB (0..1) of the map at s in [0, 1] (clamped).
std::array<double, 3> color_map_rgb(ColorMap map, double s);

// Fills `table` with 256 entries of the map over [0, range_max]; NaN values grey.
void fill_lookup_table(vtkLookupTable* table, ColorMap map, double range_max);

}  // namespace limber::render
