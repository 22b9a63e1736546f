// Concurrent access to a run directory (docs/results-format.md, "Reading a file still being
// written"). Reading a results file while its run still writes it (`limber render` and
// `limber report` on a live run): a writer process
// holds results.h5 open, flushed, with HDF5's exclusive file lock; the reader (H5Reader, the
// layer render and report open through) must open it, see every flushed sample and the status
// "running", and leave the writer able to go on and finish a complete file.
#include "results/directory_lock.h"
#include "results/h5_reader.h"
#include "results/results_layout.h"
#include "results/results_writer.h"

#include "core/error.h"

#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>

namespace limber::results {
namespace {

constexpr int kFirstSamples = 300;  // more than a block (kBlockRows = 256), then a flush
constexpr int kLaterSamples = 200;

// The writer: kFirstSamples samples and a flush, a byte on `ready`, then it waits for a byte on
// `go` (holding the file open) before kLaterSamples more and finish(). Exit status 0 on success.
[[noreturn]] void write_in_two_parts(const std::filesystem::path& dir, int ready, int go) {
  int code = 0;
  try {
    ResultsWriter writer(dir, "live", "none");
    writer.add_rigid_body({"box", {}});
    Sample sample;
    sample.bodies.resize(1);
    for (int k = 1; k <= kFirstSamples + kLaterSamples; ++k) {
      sample.time = 1e-3 * k;
      writer.append_sample(sample);
      if (k == kFirstSamples) {
        writer.flush();
        char byte = 1;
        if (write(ready, &byte, 1) != 1 || read(go, &byte, 1) != 1) _exit(2);
      }
    }
    writer.finish(RunStatus::kOk);
  } catch (...) {
    code = 1;
  }
  _exit(code);
}

TEST(LiveFileRead, AReaderSeesTheFlushedSamplesAndTheWriterFinishes) {
  const auto dir = std::filesystem::temp_directory_path() / ("limber_results_live_" + std::to_string(getpid()));
  std::filesystem::remove_all(dir);
  int ready[2], go[2];
  ASSERT_EQ(pipe(ready), 0);
  ASSERT_EQ(pipe(go), 0);
  const pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    // Only its own ends: the parent's exit (a failed test) then ends the wait with EOF.
    close(ready[0]);
    close(go[1]);
    write_in_two_parts(dir, ready[1], go[0]);
  }
  close(ready[1]);
  close(go[0]);
  char byte = 0;
  ASSERT_EQ(read(ready[0], &byte, 1), 1);

  // The writer holds the file (and HDF5's lock on it): a reader opens it all the same, twice at
  // once (two renders), and sees exactly the flushed samples with the status "running".
  {
    const H5Reader first(dir / kResultsFileName, "results file", "");
    const H5Reader second(dir / kResultsFileName, "results file", "");
    EXPECT_EQ(first.rows(layout::kTime, 0), static_cast<hsize_t>(kFirstSamples));
    EXPECT_EQ(second.rows(layout::kTime, 0), static_cast<hsize_t>(kFirstSamples));
    EXPECT_EQ(first.string_attribute("/", layout::kStatusAttribute), layout::status::kRunning);
  }

  // The writer goes on and finishes a complete file.
  ASSERT_EQ(write(go[1], &byte, 1), 1);
  int status = 0;
  ASSERT_EQ(waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 0);
  const H5Reader after(dir / kResultsFileName, "results file", "");
  EXPECT_EQ(after.rows(layout::kTime, 0), static_cast<hsize_t>(kFirstSamples + kLaterSamples));
  EXPECT_EQ(after.string_attribute("/", layout::kStatusAttribute), layout::status::kOk);
  std::filesystem::remove_all(dir);
}

TEST(RenderLock, OneRenderAtATimeBesideARun) {
  const auto dir = std::filesystem::temp_directory_path() / ("limber_render_lock_" + std::to_string(getpid()));
  std::filesystem::create_directories(dir);
  {
    // flock(2) locks belong to an open file description: a second open, even in this process,
    // is refused as another process's would be.
    const DirectoryLock render(dir, kRenderLock);
    try {
      const DirectoryLock second(dir, kRenderLock);
      ADD_FAILURE() << "expected an InputError";
    } catch (const InputError& error) {
      EXPECT_NE(std::string(error.what()).find("render"), std::string::npos) << error.what();
    }
    // A run may write into the directory while it is rendered, and the reverse.
    EXPECT_NO_THROW(DirectoryLock(dir, kRunLock));
  }
  EXPECT_NO_THROW(DirectoryLock(dir, kRenderLock));
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace limber::results
