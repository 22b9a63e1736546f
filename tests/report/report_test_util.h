// Helpers of the report tests: fresh directories, PNG pixels, links of a page.
#pragma once

#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPNGReader.h>

#include <array>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace limber::report::testing {

// An empty directory for one test, under the build tree (LIMBER_REPORT_TEST_TMP) so that
// checkouts testing on one machine at once do not clear each other's files.
inline std::filesystem::path fresh_directory(const std::string& name) {
#ifdef LIMBER_REPORT_TEST_TMP
  const std::filesystem::path root = LIMBER_REPORT_TEST_TMP;
#else
  const std::filesystem::path root = std::filesystem::temp_directory_path();
#endif
  const auto dir = root / ("limber_report_" + name);
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

inline std::string read_text(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// An RGB(A) PNG read back; pixel(x, y) with y counted from the top.
struct Png {
  int width = 0, height = 0, components = 0;
  vtkNew<vtkImageData> image;

  explicit Png(const std::filesystem::path& file) {
    vtkNew<vtkPNGReader> reader;
    reader->SetFileName(file.string().c_str());
    reader->Update();
    image->DeepCopy(reader->GetOutput());
    const int* d = image->GetDimensions();
    width = d[0];
    height = d[1];
    components = image->GetNumberOfScalarComponents();
  }
  std::array<int, 3> pixel(int x, int y) const {
    const auto* p = static_cast<const unsigned char*>(
        const_cast<vtkImageData*>(image.Get())->GetScalarPointer(x, height - 1 - y, 0));
    return {p[0], p[1], p[2]};
  }
};

// True when a pixel within `radius` px of `at` (column, row from the top) has `color` within
// `tolerance` per channel.
inline bool color_near(const Png& png, double column, double row, const std::array<unsigned char, 3>& color,
                       int radius = 3, int tolerance = 40) {
  for (int dy = -radius; dy <= radius; ++dy) {
    for (int dx = -radius; dx <= radius; ++dx) {
      const int x = static_cast<int>(std::lround(column)) + dx;
      const int y = static_cast<int>(std::lround(row)) + dy;
      if (x < 0 || y < 0 || x >= png.width || y >= png.height) continue;
      const auto p = png.pixel(x, y);
      if (std::abs(p[0] - color[0]) <= tolerance && std::abs(p[1] - color[1]) <= tolerance &&
          std::abs(p[2] - color[2]) <= tolerance) {
        return true;
      }
    }
  }
  return false;
}

// The page without the contents of its <script> elements (the inlined library and the plots'
// JSON are code and data, not markup).
inline std::string without_scripts(const std::string& html) {
  std::string out;
  std::size_t at = 0;
  while (true) {
    const std::size_t open = html.find("<script", at);
    if (open == std::string::npos) break;
    const std::size_t body = html.find('>', open);
    const std::size_t close = html.find("</script>", body);
    if (body == std::string::npos || close == std::string::npos) break;
    out += html.substr(at, body + 1 - at);
    at = close;
  }
  return out + html.substr(at);
}

// Every src="..." and href="..." value of a page's markup (script contents left out).
inline std::vector<std::string> links(const std::string& page) {
  std::vector<std::string> out;
  const std::string html = without_scripts(page);
  const std::regex attribute(R"((?:src|href)="([^"]*)\")");
  for (auto it = std::sregex_iterator(html.begin(), html.end(), attribute);
       it != std::sregex_iterator(); ++it) {
    out.push_back((*it)[1].str());
  }
  return out;
}

}  // namespace limber::report::testing
