// link_name (results/link_name.h): the documented percent-encoding, injective (checked by
// decoding every link back with the documented grammar), and the writer puts every named group
// at its link with the original text in the attribute `name`.
#include "results/link_name.h"

#include "h5_test_read.h"
#include "results/results_writer.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <optional>
#include <random>
#include <set>

namespace limber::results {
namespace {

using namespace std::string_literals;
using testing::read_doubles;
using testing::read_string_attribute;

// The inverse of link_name, written from docs/results-format.md ("Names"): "%XX" is the byte
// 0xXX, every other byte stands for itself. Nothing when `link` is not a well-formed link name.
std::optional<std::string> decode(const std::string& link) {
  std::string name;
  for (std::size_t k = 0; k < link.size(); ++k) {
    if (link[k] != '%') {
      name += link[k];
      continue;
    }
    if (k + 2 >= link.size()) return std::nullopt;
    const std::string hex = link.substr(k + 1, 2);
    if (hex.find_first_not_of("0123456789ABCDEF") != std::string::npos) return std::nullopt;
    name += static_cast<char>(std::stoi(hex, nullptr, 16));
    k += 2;
  }
  return name;
}

TEST(LinkName, LeavesOrdinaryNamesAsTheyAre) {
  for (const std::string name : {"crank", "R3", "rod 1", "arm.left", "R.1", "panel_2-b", "bras ü",
                                 "a..b", "x."}) {
    EXPECT_EQ(link_name(name), name);
  }
}

TEST(LinkName, EscapesWhatHdf5CannotHold) {
  EXPECT_EQ(link_name("arm/left"), "arm%2Fleft");
  EXPECT_EQ(link_name("50%"), "50%25");
  EXPECT_EQ(link_name("arm%2Fleft"), "arm%252Fleft");  // not the link of "arm/left"
  EXPECT_EQ(link_name("."), "%2E");
  EXPECT_EQ(link_name(".."), "%2E.");
  EXPECT_EQ(link_name(".hidden"), "%2Ehidden");
  EXPECT_EQ(link_name("a\0b"s), "a%00b");
  EXPECT_EQ(link_name("tab\there\n"), "tab%09here%0A");
  EXPECT_EQ(link_name("\x7F"), "%7F");
}

// Injective on arbitrary bytes: every link decodes back to its name; links never hold '/' or
// NUL and are never "." or "..".
TEST(LinkName, IsInjectiveOnArbitraryBytes) {
  std::mt19937 random(14);
  std::uniform_int_distribution<int> length(1, 6), byte(0, 255), pick(0, 7);
  // Mostly the bytes the mapping treats specially, to make near-collisions likely.
  const std::string special = "%/.\0\x1F\x7F"s + "2F";
  std::set<std::string> names, links;
  for (int trial = 0; trial < 20000; ++trial) {
    std::string name;
    for (int k = length(random); k > 0; --k) {
      const int p = pick(random);
      name += p < static_cast<int>(special.size()) ? special[p] : static_cast<char>(byte(random));
    }
    const std::string link = link_name(name);
    ASSERT_EQ(decode(link), name) << link;
    EXPECT_EQ(link.find('/'), std::string::npos);
    EXPECT_EQ(link.find('\0'), std::string::npos);
    EXPECT_NE(link[0], '.');
    names.insert(name);
    links.insert(link);
  }
  EXPECT_EQ(links.size(), names.size());
}

// Names that would break or collide as link names: each group at its link, the name beside it.
TEST(LinkName, WriterKeepsEveryNameInItsGroup) {
  const auto dir = std::filesystem::temp_directory_path() / "limber_results_link_names";
  std::filesystem::remove_all(dir);
  const std::vector<std::string> bodies = {"arm/left", "arm%2Fleft", ".", "..", "arm.left"};
  {
    ResultsWriter writer(dir, "names", "case.yaml");
    for (const std::string& body : bodies) writer.add_rigid_body({body, {}});
    writer.add_joint({"R.1", "revolute", "arm/left", ".."});
    writer.add_joint({"/", "revolute", "ground", "."});
    writer.add_driver(".");
    writer.add_energy("kinetic/2");
    writer.add_hinge_limit({"latch/1", "latch", "R.1", 1.0});
    Sample sample;
    sample.bodies.resize(bodies.size());
    sample.joints.resize(2);
    sample.driver_efforts = {7.0};
    sample.energies = {3.0};
    sample.hinge_limit_angles = {0.5};
    sample.hinge_limit_torques = {0.0};
    sample.hinge_limits_engaged = {0};
    writer.append_sample(sample);
    writer.finish(RunStatus::kOk);
  }
  const hid_t file = H5Fopen((dir / "results.h5").c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(file, 0);
  for (const auto& [group, name] : std::vector<std::pair<std::string, std::string>>{
           {"/bodies/arm%2Fleft", "arm/left"},
           {"/bodies/arm%252Fleft", "arm%2Fleft"},
           {"/bodies/%2E", "."},
           {"/bodies/%2E.", ".."},
           {"/bodies/arm.left", "arm.left"},
           {"/joints/R.1", "R.1"},
           {"/joints/%2F", "/"},
           {"/drivers/%2E", "."},
           {"/hinge_limits/latch%2F1", "latch/1"}}) {
    EXPECT_EQ(read_string_attribute(file, group, kNameAttribute), name) << group;
  }
  EXPECT_EQ(read_string_attribute(file, "/energy/kinetic%2F2", kNameAttribute), "kinetic/2");
  EXPECT_EQ(read_doubles(file, "/drivers/%2E/effort"), std::vector<double>{7.0});
  EXPECT_EQ(read_doubles(file, "/energy/kinetic%2F2"), std::vector<double>{3.0});
  // Joint attributes name bodies as text.
  EXPECT_EQ(read_string_attribute(file, "/joints/R.1", "body_j"), "..");
  EXPECT_EQ(read_string_attribute(file, "/hinge_limits/latch%2F1", "joint"), "R.1");
  H5Fclose(file);
}

}  // namespace
}  // namespace limber::results
