// The pictures `limber render` left in a run directory, as the report shows them: a strip of
// stills picked from DIR/frames and a link to DIR/animation.mp4.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace limber::report {

// Number of stills in a strip.
inline constexpr int kStillCount = 6;

// `count` frames evenly spread over `frames` (first and last included; all when fewer).
std::vector<std::filesystem::path> pick_stills(const std::vector<std::filesystem::path>& frames,
                                               int count = kStillCount);

// Copies `stills` into `images` as <prefix>still_<k>.png so the report folder holds them;
// returns the new file names. Throws std::filesystem::filesystem_error when a copy fails.
std::vector<std::string> copy_stills(const std::vector<std::filesystem::path>& stills,
                                     const std::filesystem::path& images, const std::string& prefix);

}  // namespace limber::report
