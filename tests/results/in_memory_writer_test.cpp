// ResultsWriter in memory (InMemoryFile) against the same writer on disk: the same declarations
// and samples give the same datasets and attributes, read by H5Reader from the file image and
// from the file (tolerance 0: the same code writes the same float64 values); and an in-memory
// writer creates nothing on disk.
#include "results/results_writer.h"

#include "core/error.h"
#include "results/h5_reader.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

namespace limber::results {
namespace {

// Declares a box and a hinge, appends `samples` samples (more than a block, kBlockRows) whose
// values encode the index, and finishes the file.
void write_run(ResultsWriter& writer, int samples) {
  writer.add_rigid_body({"box", {ShapeSpec{}}});
  writer.add_joint({"hinge", "revolute", "ground", "box"});
  writer.add_energy("kinetic");
  for (int k = 0; k < samples; ++k) {
    Sample sample;
    sample.time = 1e-3 * k;
    sample.bodies.resize(1);
    sample.bodies[0].position = {1.0 * k, 2.0, 0.5 / (k + 1)};
    sample.joints.resize(1);
    sample.joints[0].force_joint = {0.1 * k, -3.0, 1.0 / 3.0};
    sample.energies = {0.5 * k * k};
    sample.steps = 2 * k;
    writer.append_sample(sample);
  }
  writer.finish(RunStatus::kInaccurate, "a message");
}

TEST(InMemoryResultsWriter, HoldsTheFileTheDiskWriterWrites) {
  const int samples = static_cast<int>(kBlockRows) + 17;
  const auto dir = std::filesystem::temp_directory_path() / "limber_results_in_memory";
  std::filesystem::remove_all(dir);
  ResultsWriter on_disk(dir, "a title", "case.yaml");
  write_run(on_disk, samples);
  ResultsWriter in_memory(InMemoryFile{}, "a title", "case.yaml");
  write_run(in_memory, samples);
  EXPECT_TRUE(in_memory.path().empty());
  EXPECT_TRUE(on_disk.file_image().empty());
  ASSERT_FALSE(in_memory.file_image().empty());

  const H5Reader file(dir / kResultsFileName, "results file", "");
  const H5Reader image(in_memory.file_image(), "results.h5", "results file");
  for (const char* dataset : {"/time", "/bodies/box/position", "/joints/hinge/force_joint", "/energy/kinetic"}) {
    const std::vector<hsize_t> dims = file.dims(dataset);
    EXPECT_EQ(image.dims(dataset), dims) << dataset;
    EXPECT_EQ(image.read<double>(dataset, H5T_NATIVE_DOUBLE, dims[0]),
              file.read<double>(dataset, H5T_NATIVE_DOUBLE, dims[0])) << dataset;
  }
  EXPECT_EQ(image.dims("/time"), (std::vector<hsize_t>{static_cast<hsize_t>(samples)}));
  EXPECT_EQ(image.read<double>("/bodies/box/position", H5T_NATIVE_DOUBLE, 3)[8], 0.5 / 3);
  EXPECT_EQ(image.attribute_texts("/"), file.attribute_texts("/"));
  EXPECT_EQ(image.string_attribute("/", "status"), "ok_inaccurate");
  EXPECT_EQ(image.members("/joints"), file.members("/joints"));
  std::filesystem::remove_all(dir);
}

TEST(InMemoryResultsWriter, WritesNothingOnDisk) {
  const auto dir = std::filesystem::temp_directory_path() / "limber_results_in_memory_cwd";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const std::filesystem::path cwd = std::filesystem::current_path();
  std::filesystem::current_path(dir);
  {
    ResultsWriter first(InMemoryFile{}, "first", "a.yaml");
    ResultsWriter second(InMemoryFile{}, "second", "b.yaml");  // two at once: each its own file
    write_run(first, 3);
    write_run(second, 5);
    EXPECT_EQ(H5Reader(first.file_image(), "first", "results file").dims("/time"), (std::vector<hsize_t>{3}));
    EXPECT_EQ(H5Reader(second.file_image(), "second", "results file").string_attribute("/", "title"), "second");
  }
  std::filesystem::current_path(cwd);
  EXPECT_TRUE(std::filesystem::is_empty(dir));
  std::filesystem::remove_all(dir);
}

TEST(InMemoryResultsWriter, BytesThatAreNotHdf5AreAnInputError) {
  const std::vector<unsigned char> not_hdf5(64, 'x');
  EXPECT_THROW(H5Reader(not_hdf5, "results.h5", "results file"), InputError);
  EXPECT_THROW(H5Reader(std::vector<unsigned char>{}, "results.h5", "results file"), InputError);
}

}  // namespace
}  // namespace limber::results
