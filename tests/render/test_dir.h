// A fresh temporary directory per test name.
#pragma once

#include <filesystem>
#include <string>

namespace limber::render::testing {

inline std::filesystem::path fresh_directory(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / ("limber_render_" + name);
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

}  // namespace limber::render::testing
