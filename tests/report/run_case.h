// `limber run` of a case into a fresh test directory, for the report tests that read real runs
// (LIMBER_EXE: the built limber, a compile definition of the test executable).
#pragma once

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "report_test_util.h"

namespace limber::report::testing {

// Runs `limber run CASE -o DIR` (once per directory name in this process).
inline std::filesystem::path run_case(const std::string& case_file, const std::string& name,
                               const std::string& extra = "") {
  const std::filesystem::path dir = testing::fresh_directory("frames_" + name);
  const std::string command = std::string(LIMBER_EXE) + " run " + case_file + " -o " + dir.string() +
                              " " + extra + " > " + (dir / "run.log").string() + " 2>&1";
  EXPECT_EQ(std::system(command.c_str()), 0) << testing::read_text(dir / "run.log");
  return dir;
}

}  // namespace limber::report::testing
