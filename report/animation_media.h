// The pictures `limber render` left in a run directory, as the report shows them: a strip of
// stills picked from DIR/frames and DIR/animation.mp4, both put inside the report folder.
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

// Puts `video` into the report folder as `folder`/<prefix>animation.mp4 — a hard link when
// both sit on one file system, else a copy — so the report can be zipped and mailed; returns
// the new file name. Throws std::filesystem::filesystem_error when neither works.
std::string place_video(const std::filesystem::path& video, const std::filesystem::path& folder,
                        const std::string& prefix);

}  // namespace limber::report
