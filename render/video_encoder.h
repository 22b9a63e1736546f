// Assembles PNG frames into DIR/animation.mp4 (H.264, yuv420p) and optionally an animated GIF
// by running the `ffmpeg` program (Debian package ffmpeg). No shell is involved.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

namespace limber::render {

// Path of `ffmpeg` on PATH, if any.
std::optional<std::filesystem::path> find_ffmpeg();

// Encodes frames/frame_%05d.png at `fps` into `output` (.mp4: H.264; .gif: palette-optimised,
// at most 15 frames/s and 640 pixels wide). Returns "" on success, else ffmpeg's complaint
// (the caller reports it; frames stay on disk either way).
std::string encode_video(const std::filesystem::path& ffmpeg,
                         const std::filesystem::path& frame_directory, double fps,
                         const std::filesystem::path& output);

}  // namespace limber::render
