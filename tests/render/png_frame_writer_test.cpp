// PNG frames: our encoder (png_encoding.h: own chunk writer, libdeflate's deflate) read back
// by a second, independent decoder (VTK's PNG reader on libpng, which checks every chunk CRC
// and the zlib Adler-32) must give the very pixels encoded: PNG is lossless, so the tolerance
// is zero. The writer pool must leave every frame complete, in order, and report a failure
// naming the file.
#include "png_encoding.h"
#include "png_frame_writer.h"
#include "test_dir.h"

#include <gtest/gtest.h>

#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPNGReader.h>

#include <cstdio>
#include <fstream>
#include <random>

namespace limber::render {
namespace {

// A frame-like test image: flat background, a gradient, a band of noise (incompressible, so
// the deflate stream holds literals and matches) and a marker value in the first pixel.
Image test_image(int width, int height, int marker) {
  Image image;
  image.width = width;
  image.height = height;
  image.rgb.resize(3 * static_cast<std::size_t>(width) * height);
  std::mt19937 random(static_cast<unsigned>(marker));
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      std::uint8_t* p = image.rgb.data() + 3 * (static_cast<std::size_t>(y) * width + x);
      if (y < height / 3) {
        p[0] = 219, p[1] = 227, p[2] = 237;
      } else if (y < 2 * height / 3) {
        p[0] = static_cast<std::uint8_t>(255 * x / width);
        p[1] = static_cast<std::uint8_t>(255 * y / height);
        p[2] = 40;
      } else {
        for (int c = 0; c < 3; ++c) p[c] = static_cast<std::uint8_t>(random());
      }
    }
  }
  image.rgb[0] = static_cast<std::uint8_t>(marker);
  return image;
}

// Decodes `file` with VTK's PNG reader into rows from the top; empty when it cannot.
Image decode(const std::filesystem::path& file) {
  vtkNew<vtkPNGReader> reader;
  if (!reader->CanReadFile(file.c_str())) return {};
  reader->SetFileName(file.c_str());
  reader->Update();
  vtkImageData* data = reader->GetOutput();
  int dims[3];
  data->GetDimensions(dims);
  if (data->GetNumberOfScalarComponents() != 3 || data->GetScalarType() != VTK_UNSIGNED_CHAR) return {};
  Image image;
  image.width = dims[0];
  image.height = dims[1];
  const auto* rows = static_cast<const std::uint8_t*>(data->GetScalarPointer());
  const std::size_t row = 3 * static_cast<std::size_t>(image.width);
  for (int y = image.height - 1; y >= 0; --y) {
    image.rgb.insert(image.rgb.end(), rows + y * row, rows + (y + 1) * row);
  }
  return image;
}

void write_bytes(const std::vector<std::uint8_t>& bytes, const std::filesystem::path& file) {
  std::ofstream out(file, std::ios::binary);
  out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
}

TEST(PngEncoding, DecodesToTheSamePixelsForEveryFilterAndLevel) {
  const auto dir = testing::fresh_directory("png_encoding");
  // Odd sizes: rows whose byte count is not a multiple of anything convenient.
  for (const auto& [width, height] : {std::pair{37, 23}, std::pair{1, 1}, std::pair{640, 3}}) {
    const Image image = test_image(width, height, 7);
    for (const PngFilter filter : {PngFilter::kNone, PngFilter::kSub}) {
      for (const int level : {0, 1, 4, 12}) {
        PngEncoder encoder({filter, level});
        const auto file = dir / ("image_" + std::to_string(width) + "_" + std::to_string(level) + ".png");
        write_bytes(encoder.encode(image), file);
        const Image back = decode(file);
        ASSERT_EQ(back.width, width) << file;
        ASSERT_EQ(back.height, height) << file;
        EXPECT_TRUE(back.rgb == image.rgb) << "filter " << static_cast<int>(filter) << ", level " << level;
      }
    }
  }
}

TEST(PngEncoding, SubFilterMakesAFrameSmallerThanNoFilter) {
  // Rows of a gradient differ from their left neighbour by a constant: Sub turns them into
  // runs, which deflate shrinks (the reason it is the default).
  Image image = test_image(320, 240, 1);
  std::fill(image.rgb.begin() + image.rgb.size() * 2 / 3, image.rgb.end(), std::uint8_t{200});
  PngEncoder none({PngFilter::kNone, 4});
  PngEncoder sub({PngFilter::kSub, 4});
  const std::size_t plain = none.encode(image).size();
  EXPECT_LT(sub.encode(image).size(), plain);
}

TEST(PngFrameWriter, WritesEveryFrameCompleteAndInOrderWithSeveralWorkers) {
  const auto dir = testing::fresh_directory("png_writer");
  constexpr int kFrames = 24;
  {
    PngFrameWriter writer(3, 2);
    for (int k = 0; k < kFrames; ++k) {
      writer.push(test_image(64 + k, 48, k), dir / ("frame_" + std::to_string(k) + ".png"));
    }
    writer.finish();
  }
  int files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    EXPECT_EQ(entry.path().extension(), ".png") << entry.path();  // no ".part" left
    ++files;
  }
  EXPECT_EQ(files, kFrames);
  for (int k = 0; k < kFrames; ++k) {
    const Image back = decode(dir / ("frame_" + std::to_string(k) + ".png"));
    EXPECT_TRUE(back.rgb == test_image(64 + k, 48, k).rgb) << "frame " << k;
  }
}

TEST(PngFrameWriter, AFailureNamesTheFileAndNoLaterFrameIsWritten) {
  const auto dir = testing::fresh_directory("png_writer_failure");
  const auto missing = dir / "no_such_folder" / "frame_1.png";
  std::string message;
  try {
    PngFrameWriter writer(2, 1);
    writer.push(test_image(32, 32, 0), dir / "frame_0.png");
    writer.push(test_image(32, 32, 1), missing);
    for (int k = 2; k < 8; ++k) writer.push(test_image(32, 32, k), dir / ("frame_" + std::to_string(k) + ".png"));
    writer.finish();
  } catch (const std::runtime_error& error) {
    message = error.what();
  }
  EXPECT_NE(message.find(missing.string()), std::string::npos) << message;
  EXPECT_TRUE(std::filesystem::exists(dir / "frame_0.png"));
  int files = 0;
  for ([[maybe_unused]] const auto& entry : std::filesystem::directory_iterator(dir)) ++files;
  EXPECT_EQ(files, 1);  // frame_0.png only: nothing after the failed frame, no ".part" file
}

}  // namespace
}  // namespace limber::render
