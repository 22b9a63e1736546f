// Checked access to a YAML document: every value knows its place in the file, and
// every failure is an InputError "file:line:col: expected ..., got ..." (house style §11).
//
// Rules enforced here for all case-file readers:
//  - a map may only hold the keys its reader allows (unknown keys are errors that list
//    the allowed keys; duplicate keys are errors too);
//  - a missing required key names the key and points at the enclosing map;
//  - typed getters reject anything that is not exactly the requested type
//    ("1.5" is not an integer, "1e3x" is not a number, NaN and infinities are refused).
// Locations are 1-based (yaml-cpp marks are 0-based).
#pragma once

#include <yaml-cpp/yaml.h>

#include <Eigen/Core>
#include <filesystem>
#include <initializer_list>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "core/error.h"

namespace limber::io {

class YamlValue {
 public:
  // `file` is the name used in messages; `name` is how the value is called in messages
  // (a key such as "E", or "beams[2]" for a sequence item).
  YamlValue(YAML::Node node, std::shared_ptr<const std::string> file, std::string name);

  const std::string& name() const { return name_; }
  SourceLocation where() const;
  // Where the key of a map entry is (entries()), e.g. to point at a bad name; where() otherwise.
  SourceLocation key_where() const;
  // Throws InputError(message) at this value's location.
  [[noreturn]] void fail(const std::string& message) const;

  bool is_map() const { return node_.IsMap(); }
  bool is_sequence() const { return node_.IsSequence(); }
  bool is_scalar() const { return node_.IsScalar(); }
  bool is_null() const { return node_.IsNull(); }

  // --- maps ---
  // Throws unless this is a map whose keys are all in `allowed` (and none repeats).
  void allow_only(std::initializer_list<std::string_view> allowed) const;
  // The entry when the key is present (its value may be null), or nothing.
  // Throws unless this is a map.
  std::optional<YamlValue> find(std::string_view key) const;
  // Required entry: throws "missing required key 'E' in <name>" at this map.
  YamlValue at(std::string_view key) const;
  // Entries in file order, with key locations, then the base's entries whose keys this map
  // does not hold (with_base); throws unless this is a map.
  std::vector<std::pair<std::string, YamlValue>> entries() const;
  // This map, with the keys it does not hold taken from `base` (another file's map: each entry
  // keeps its own file and line in messages). Used for a case's `base:` file.
  YamlValue with_base(const YamlValue& base) const;

  // --- sequences ---
  // Items in order (named "<name>[i]"); throws unless this is a sequence.
  std::vector<YamlValue> items() const;

  // --- scalars (each throws "expected <what> for '<name>', got '<text>'") ---
  std::string as_string() const;       // any non-empty scalar
  double as_number() const;            // finite real
  double as_positive() const;          // > 0
  double as_non_negative() const;      // >= 0
  int as_integer() const;              // whole number within int range
  int as_positive_integer() const;     // >= 1
  bool as_bool() const;                // true / false
  Eigen::Vector3d as_vector3() const;  // sequence of exactly 3 numbers
  // One of `choices` (the message lists them).
  std::string as_choice(std::initializer_list<std::string_view> choices) const;
  // A regular file named by this scalar, relative to the folder of the file that holds it;
  // `what` says what it is ("a bulk-data file"): "expected a bulk-data file, got 'x.bdf' (no
  // such file)", and "file name too long" and the like (core/input_file.h).
  std::filesystem::path as_existing_file(std::string_view what) const;

  // The underlying node (for readers that need yaml-cpp directly).
  const YAML::Node& node() const { return node_; }

 private:
  std::string scalar_text() const;  // throws unless a scalar
  YAML::Node node_;
  std::shared_ptr<const std::string> file_;
  std::string name_;
  YAML::Mark key_mark_;  // set for map entries: where the key is, used when the value has none
  std::shared_ptr<const YamlValue> base_;  // keys this map does not hold (with_base)
  friend class YamlDocument;
};

// A parsed YAML file. Syntax errors throw InputError at file:line:col.
class YamlDocument {
 public:
  // Reads and parses `path`; throws InputError when it cannot be read or parsed.
  static YamlDocument load_file(const std::string& path);
  // Parses `text`; `file` names it in messages.
  static YamlDocument load_text(const std::string& text, const std::string& file);

  // The top-level value (named "the case file" in messages).
  YamlValue root() const;
  const std::string& file() const { return *file_; }

 private:
  YamlDocument(YAML::Node root, std::shared_ptr<const std::string> file);
  YAML::Node root_;
  std::shared_ptr<const std::string> file_;
};

// 1-based location of a yaml-cpp mark in `file` (line/column 0 when the mark is null).
SourceLocation location_of(const YAML::Mark& mark, const std::string& file);

}  // namespace limber::io
