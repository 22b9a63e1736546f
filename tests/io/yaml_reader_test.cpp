// The YAML access layer: locations, typed getters, unknown and missing keys.
#include "io/yaml_reader.h"

#include <gtest/gtest.h>

#include "input_error_matchers.h"

namespace limber::io {
namespace {

using test::location_of;

// The error an action throws, or a failed test.
template <typename Action>
std::string error_of(Action action) {
  try {
    action();
  } catch (const InputError& error) {
    return error.what();
  }
  ADD_FAILURE() << "expected an InputError";
  return {};
}

TEST(YamlReader, LocationsAreOneBasedLineAndColumn) {
  const std::string text = "a:\n  b: 12\n  c: [1, 2, 3]\n";
  const YamlValue root = YamlDocument::load_text(text, "test.yaml").root();
  EXPECT_EQ(root.at("a").at("b").where().to_string(), location_of(text, "12"));
  EXPECT_EQ(root.at("a").at("c").items()[2].where().to_string(), location_of(text, "3]"));
  EXPECT_EQ(root.at("a").at("b").as_integer(), 12);
}

TEST(YamlReader, TypedGettersNameTheKeyAndTheValue) {
  const std::string text =
      "E: -1\nn: 1.5\nx: 1e3x\nv: [1, 2]\nflag: yes\nshape: hexagon\nrho: 7820\n";
  const YamlValue root = YamlDocument::load_text(text, "test.yaml").root();
  EXPECT_EQ(error_of([&] { root.at("E").as_positive(); }),
            location_of(text, "-1") + ": expected a positive number for 'E', got '-1'");
  EXPECT_EQ(error_of([&] { root.at("n").as_positive_integer(); }),
            location_of(text, "1.5") + ": expected a positive whole number for 'n', got '1.5'");
  EXPECT_EQ(error_of([&] { root.at("x").as_number(); }),
            location_of(text, "1e3x") + ": expected a number for 'x', got '1e3x'");
  EXPECT_EQ(error_of([&] { root.at("v").as_vector3(); }),
            location_of(text, "[1, 2]") + ": expected 3 numbers [x, y, z] for 'v', got 2 values");
  EXPECT_EQ(error_of([&] { root.at("flag").as_bool(); }),
            location_of(text, "yes") + ": expected true or false for 'flag', got 'yes'");
  EXPECT_NE(error_of([&] {
              root.at("shape").as_choice({"rectangle", "circle"});
            }).find("expected one of rectangle, circle for 'shape', got 'hexagon'"),
            std::string::npos);
  // Exact values pass through unchanged.
  EXPECT_EQ(root.at("rho").as_positive(), 7820.0);
}

TEST(YamlReader, UnknownKeysListTheAllowedOnes) {
  const std::string text = "steel: {E: 1, nu: 0.3, rho: 2, density: 3}\n";
  const YamlValue steel = YamlDocument::load_text(text, "test.yaml").root().at("steel");
  EXPECT_EQ(error_of([&] {
              steel.allow_only({"E", "nu", "rho"});
            }),
            location_of(text, "density") +
                ": unknown key 'density' in 'steel'; expected one of: E, nu, rho");
}

TEST(YamlReader, MissingKeysPointAtTheEnclosingMap) {
  const std::string text = "steel: {E: 1, nu: 0.3}\n";
  const YamlValue steel = YamlDocument::load_text(text, "test.yaml").root().at("steel");
  EXPECT_EQ(error_of([&] { steel.at("rho"); }),
            location_of(text, "{") + ": missing required key 'rho' in 'steel'");
}

TEST(YamlReader, DuplicateKeysAreErrors) {
  const std::string text = "a: 1\nb: 2\na: 3\n";
  const YamlValue root = YamlDocument::load_text(text, "test.yaml").root();
  EXPECT_EQ(error_of([&] { root.entries(); }),
            location_of(text, "a", 1) + ": duplicate key 'a' in 'the case file'");
}

TEST(YamlReader, SyntaxErrorsCarryTheLine) {
  const std::string text = "title: ok\nmaterials: {steel: [1, 2}\n";
  const std::string message = error_of([&] { YamlDocument::load_text(text, "test.yaml"); });
  EXPECT_EQ(message.rfind("test.yaml:2:", 0), 0u) << message;
  EXPECT_NE(message.find("YAML syntax error"), std::string::npos) << message;
}

TEST(YamlReader, MissingFileIsAnInputError) {
  EXPECT_NE(error_of([] {
              YamlDocument::load_file("/nonexistent/case.yaml");
            }).find("cannot open the case file '/nonexistent/case.yaml'"),
            std::string::npos);
}

}  // namespace
}  // namespace limber::io
