#include "animation_media.h"

#include "results/file_names.h"

namespace limber::report {

std::vector<std::filesystem::path> pick_stills(const std::vector<std::filesystem::path>& frames,
                                               int count) {
  const auto n = static_cast<int>(frames.size());
  if (n <= count) return frames;
  std::vector<std::filesystem::path> stills;
  // Index k (n - 1) / (count - 1), rounded: first and last frame included.
  for (int k = 0; k < count; ++k) {
    stills.push_back(frames[static_cast<std::size_t>((2 * k * (n - 1) + (count - 1)) / (2 * (count - 1)))]);
  }
  return stills;
}

std::vector<std::string> copy_stills(const std::vector<std::filesystem::path>& stills,
                                     const std::filesystem::path& images, const std::string& prefix) {
  std::vector<std::string> names;
  for (std::size_t k = 0; k < stills.size(); ++k) {
    names.push_back(prefix + "still_" + std::to_string(k) + ".png");
    std::filesystem::copy_file(stills[k], images / names.back(),
                               std::filesystem::copy_options::overwrite_existing);
  }
  return names;
}

std::string place_video(const std::filesystem::path& video, const std::filesystem::path& folder,
                        const std::string& prefix) {
  const std::string name = prefix + results::kAnimationVideoFileName;
  const std::filesystem::path target = folder / name;
  std::filesystem::remove(target);
  std::error_code error;
  std::filesystem::create_hard_link(video, target, error);
  if (error) std::filesystem::copy_file(video, target);
  return name;
}

}  // namespace limber::report
