// What an engineer orients by in a frame: a world triad (arrows along ground x, y, z, red,
// green, blue, labelled) whose arrows have a round length, stated beside it, so the triad is
// also the picture's length scale. Internal to limber_render (exposes VTK types).
#pragma once

#include <Eigen/Core>

#include <array>
#include <string>

class vtkRenderer;

namespace limber::render {

// A round length (1, 2 or 5 times a power of ten) near `about` [m]; `about` > 0.
double round_length(double about);

// Adds the triad at `origin` (ground) with arrows `length` [m] long and labels of `font`
// pixels ("x", "y" at the tips, "z (arrows <length> m)" above the z tip; `names` replace
// x, y, z).
void add_world_triad(vtkRenderer* renderer, const Eigen::Vector3d& origin, double length,
                     int font, const std::array<std::string, 3>& names = {"x", "y", "z"});

}  // namespace limber::render
