// Names are free text (docs/case-format.md): the rigid slider-crank with bodies "arm/left",
// "arm%2Fleft" (the first one's link name) and "arm.left", joints "R.1", ".." and "R~2E1" (the
// first one's file stem) and a driver "." runs, renders and reports end to end as a user runs
// `limber` (popen); each name keeps its own group, VTU files and plots. A name with a NUL or
// another control character is an input error at its key.
#include <gtest/gtest.h>
#include <hdf5.h>

#include <algorithm>
#include <array>
#include <filesystem>
#include <string>
#include <vector>

#include "../results/h5_test_read.h"
#include "run_test_support.h"

namespace limber {
namespace {

using results::testing::dataset_dims;
using results::testing::read_string_attribute;

test::CommandRun run_limber(const std::string& args) { return test::run_command(LIMBER_EXE, args); }

const std::string kCase = std::string(LIMBER_CASES_DIR) + "/slider_crank_rigid.yaml";

// `text` with each `from` replaced once by `to` (throws when one is absent).
std::string renamed(std::string text, const std::vector<std::pair<std::string, std::string>>& edits) {
  for (const auto& [from, to] : edits) {
    const std::size_t at = text.find(from);
    if (at == std::string::npos) throw std::runtime_error("renamed: '" + from + "' not in the case");
    text.replace(at, from.size(), to);
  }
  return text;
}

// crank -> "arm%2Fleft", rod -> "arm/left", slider -> "arm.left"; R1 -> "R.1", R2 -> "..",
// R3 -> "R~2E1"; D1 -> ".".
std::string free_text_case() {
  return renamed(test::read_text(kCase),
                 {{"  crank:\n", "  \"arm%2Fleft\":\n"},
                  {"  rod:\n", "  \"arm/left\":\n"},
                  {"  slider:\n", "  \"arm.left\":\n"},
                  {"  R1: {type: revolute, body_i: ground, body_j: crank,",
                   "  \"R.1\": {type: revolute, body_i: ground, body_j: \"arm%2Fleft\","},
                  {"  R2: {type: revolute, body_i: crank, body_j: rod,",
                   "  \"..\": {type: revolute, body_i: \"arm%2Fleft\", body_j: \"arm/left\","},
                  {"  R3: {type: revolute, body_i: rod, body_j: slider,",
                   "  \"R~2E1\": {type: revolute, body_i: \"arm/left\", body_j: \"arm.left\","},
                  {"body_i: ground, body_j: slider,", "body_i: ground, body_j: \"arm.left\","},
                  {"  D1:\n    joint: R1\n", "  \".\":\n    joint: \"R.1\"\n"}});
}

TEST(NamesCli, FreeTextNamesRunRenderAndReport) {
  const auto dir = test::fresh_directory("names");
  const std::string case_file = test::write_case("names", free_text_case());
  const test::CommandRun run = run_limber("run " + case_file + " -o " + dir.string() + " --t-end 0.02");
  ASSERT_EQ(run.exit_code, 0) << run.err;

  // results.h5: every name at its link name (docs/results-format.md), the text beside it.
  const hid_t file = H5Fopen((dir / "results.h5").c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(file, 0);
  for (const auto& [group, name] : std::vector<std::pair<std::string, std::string>>{
           {"/bodies/arm%2Fleft", "arm/left"},
           {"/bodies/arm%252Fleft", "arm%2Fleft"},
           {"/bodies/arm.left", "arm.left"},
           {"/joints/R.1", "R.1"},
           {"/joints/%2E.", ".."},
           {"/joints/R~2E1", "R~2E1"},
           {"/drivers/%2E", "."}}) {
    EXPECT_EQ(read_string_attribute(file, group, "name"), name) << group;
  }
  EXPECT_EQ(dataset_dims(file, "/drivers/%2E/effort"), std::vector<hsize_t>{21});
  EXPECT_EQ(read_string_attribute(file, "/joints/%2E.", "body_j"), "arm/left");
  H5Fclose(file);

  // render: one VTU series per body under distinct safe names, the names in the PVD; the XDMF
  // scene names each body's value of cell data `body`, and scene.h5 has its group at its link
  // name.
  const test::CommandRun render =
      run_limber("render " + dir.string() + " --no-video --size 320x180 --no-progress --paraview both");
  ASSERT_EQ(render.exit_code, 0) << render.err;
  for (const char* stem : {"arm~2Fleft", "arm~252Fleft", "arm~2Eleft"}) {
    EXPECT_TRUE(std::filesystem::is_regular_file(dir / "vtk" / (std::string(stem) + "_00020.vtu")))
        << stem;
  }
  const std::string pvd = test::read_text((dir / "vtk" / "scene.pvd").string());
  EXPECT_NE(pvd.find("name=\"arm%2Fleft\" file=\"arm~252Fleft_00000.vtu\""), std::string::npos);
  const std::string xmf = test::read_text((dir / "vtk" / "scene.xmf").string());
  const hid_t scene = H5Fopen((dir / "vtk" / "scene.h5").string().c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(scene, 0);
  for (const auto& [group, name] : std::vector<std::pair<std::string, std::string>>{
           {"/bodies/arm%2Fleft", "arm/left"},
           {"/bodies/arm%252Fleft", "arm%2Fleft"},
           {"/bodies/arm.left", "arm.left"}}) {
    EXPECT_EQ(read_string_attribute(scene, group, "name"), name) << group;
    int index = -1;
    const hid_t attribute = H5Aopen_by_name(scene, group.c_str(), "index", H5P_DEFAULT, H5P_DEFAULT);
    ASSERT_GE(attribute, 0) << group;
    H5Aread(attribute, H5T_NATIVE_INT, &index);
    H5Aclose(attribute);
    EXPECT_NE(xmf.find("<Information Name=\"body " + std::to_string(index) + "\" Value=\"" + name + "\"/>"), std::string::npos)
        << name;
  }
  H5Fclose(scene);

  // report: a reaction plot per joint, named apart, and the names on the page.
  const test::CommandRun report = run_limber("report " + dir.string());
  ASSERT_EQ(report.exit_code, 0) << report.err;
  for (const char* stem : {"R~2E1", "~2E~2E", "R~7E2E1"}) {
    EXPECT_TRUE(std::filesystem::is_regular_file(dir / "report" / "images" /
                                                 ("run1_reaction_" + std::string(stem) + "_force_ground.png")))
        << stem;
  }
  const std::string html = test::read_text((dir / "report" / "index.html").string());
  for (const char* text : {"joint R.1 on arm%2Fleft", "joint .. on arm/left", "joint R~2E1 on arm.left"}) {
    EXPECT_NE(html.find(text), std::string::npos) << text;
  }
}

// Control characters are not text: exit 1 with the key's file:line:col.
TEST(NamesCli, ControlCharactersInNamesAreInputErrors) {
  const std::string text = free_text_case();
  for (const auto& [from, to, message] : std::vector<std::array<std::string, 3>>{
           {"  \"arm/left\":\n", "  \"arm\\0left\":\n",
            "body name: expected text without control characters, got \"arm\\x00left\" (byte 0x00 at 3)"},
           {"  \"..\": {", "  \"R\\t2\": {",
            "joint name: expected text without control characters, got \"R\\x092\" (byte 0x09 at 1)"},
           {"  \".\":\n", "  \"D\\n1\":\n",
            "driver name: expected text without control characters, got \"D\\x0A1\" (byte 0x0A at 1)"}}) {
    const std::string edited = renamed(text, {{from, to}});
    const std::size_t line = std::count(edited.begin(), edited.begin() + edited.find(to), '\n') + 1;
    const std::string case_file = test::write_case("names_control", edited);
    const auto dir = test::fresh_directory("names_control");
    const test::CommandRun run = run_limber("run " + case_file + " -o " + dir.string());
    EXPECT_EQ(run.exit_code, 1) << run.err;
    EXPECT_NE(run.err.find(case_file + ":" + std::to_string(line) + ":3: " + message), std::string::npos)
        << run.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "results.h5"));
  }
}

}  // namespace
}  // namespace limber
