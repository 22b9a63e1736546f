#include "io/yaml_reader.h"

#include <charconv>
#include <cmath>
#include <fstream>
#include <limits>
#include <set>
#include <sstream>

#include "core/input_file.h"

namespace limber::io {

namespace {

std::string join(std::initializer_list<std::string_view> words) {
  std::string text;
  for (std::string_view word : words) {
    if (!text.empty()) text += ", ";
    text += word;
  }
  return text;
}

// Parses the whole of `text` as a finite double (a leading '+' allowed).
std::optional<double> parse_number(std::string_view text) {
  if (!text.empty() && text.front() == '+') text.remove_prefix(1);
  double value = 0.0;
  const char* end = text.data() + text.size();
  auto [last, error] = std::from_chars(text.data(), end, value);
  if (text.empty() || error != std::errc() || last != end || !std::isfinite(value)) return {};
  return value;
}

// Parses the whole of `text` as an int (a leading '+' allowed).
std::optional<int> parse_integer(std::string_view text) {
  if (!text.empty() && text.front() == '+') text.remove_prefix(1);
  int value = 0;
  const char* end = text.data() + text.size();
  auto [last, error] = std::from_chars(text.data(), end, value);
  if (text.empty() || error != std::errc() || last != end) return {};
  return value;
}

}  // namespace

SourceLocation location_of(const YAML::Mark& mark, const std::string& file) {
  if (mark.is_null()) return SourceLocation{file, 0, 0};
  return SourceLocation{file, mark.line + 1, mark.column + 1};
}

YamlValue::YamlValue(YAML::Node node, std::shared_ptr<const std::string> file, std::string name)
    : node_(std::move(node)),
      file_(std::move(file)),
      name_(std::move(name)),
      key_mark_(YAML::Mark::null_mark()) {}

SourceLocation YamlValue::where() const {
  // Values parsed from the file carry their own mark; empty values fall back to their key.
  YAML::Mark mark = node_.Mark();
  if (mark.is_null() || (node_.IsNull() && !key_mark_.is_null())) mark = key_mark_;
  return location_of(mark, *file_);
}

SourceLocation YamlValue::key_where() const {
  return key_mark_.is_null() ? where() : location_of(key_mark_, *file_);
}

void YamlValue::fail(const std::string& message) const { throw InputError(message, where()); }

std::vector<std::pair<std::string, YamlValue>> YamlValue::entries() const {
  if (!is_map()) {
    const char* got = is_sequence() ? "a sequence" : is_scalar() ? "a single value" : "nothing";
    fail("expected a map of 'key: value' entries for '" + name_ + "', got " + got);
  }
  std::vector<std::pair<std::string, YamlValue>> result;
  std::set<std::string> seen;
  for (auto it = node_.begin(); it != node_.end(); ++it) {
    // Keys are plain words, each used once.
    const SourceLocation key_where = location_of(it->first.Mark(), *file_);
    if (!it->first.IsScalar()) {
      throw InputError("expected a plain key in '" + name_ + "', got a " +
                           (it->first.IsMap() ? std::string("map") : std::string("sequence")),
                       key_where);
    }
    const std::string key = it->first.Scalar();
    if (!seen.insert(key).second) {
      throw InputError("duplicate key '" + key + "' in '" + name_ + "'", key_where);
    }
    YamlValue value(it->second, file_, key);
    value.key_mark_ = it->first.Mark();
    result.emplace_back(key, std::move(value));
  }
  // Then the base's entries this map does not override.
  if (base_) {
    for (auto& [key, value] : base_->entries()) {
      if (seen.insert(key).second) result.emplace_back(key, std::move(value));
    }
  }
  return result;
}

void YamlValue::allow_only(std::initializer_list<std::string_view> allowed) const {
  for (const auto& [key, value] : entries()) {
    bool known = false;
    for (std::string_view word : allowed) known = known || word == key;
    if (!known) {
      throw InputError(
          "unknown key '" + key + "' in '" + name_ + "'; expected one of: " + join(allowed),
          location_of(value.key_mark_, *value.file_));
    }
  }
}

YamlValue YamlValue::with_base(const YamlValue& base) const {
  YamlValue layered = *this;
  layered.base_ = std::make_shared<const YamlValue>(base);
  return layered;
}

std::optional<YamlValue> YamlValue::find(std::string_view key) const {
  for (auto& [name, value] : entries()) {
    if (name == key) return std::move(value);
  }
  return std::nullopt;
}

YamlValue YamlValue::at(std::string_view key) const {
  std::optional<YamlValue> value = find(key);
  if (!value) fail("missing required key '" + std::string(key) + "' in '" + name_ + "'");
  return std::move(*value);
}

std::vector<YamlValue> YamlValue::items() const {
  if (!is_sequence()) {
    const char* got = is_map() ? "a map" : is_scalar() ? "a single value" : "nothing";
    fail("expected a sequence [...] for '" + name_ + "', got " + got);
  }
  std::vector<YamlValue> result;
  for (std::size_t i = 0; i < node_.size(); ++i) {
    result.emplace_back(node_[i], file_, name_ + "[" + std::to_string(i) + "]");
  }
  return result;
}

std::string YamlValue::scalar_text() const {
  if (is_scalar()) return node_.Scalar();
  const char* got = is_map() ? "a map" : is_sequence() ? "a sequence" : "nothing";
  fail("expected a value for '" + name_ + "', got " + got);
}

std::string YamlValue::as_string() const {
  std::string text = scalar_text();
  if (text.empty()) fail("expected a non-empty text for '" + name_ + "', got ''");
  return text;
}

double YamlValue::as_number() const {
  const std::string text = scalar_text();
  std::optional<double> value = parse_number(text);
  if (!value) fail("expected a number for '" + name_ + "', got '" + text + "'");
  return *value;
}

double YamlValue::as_positive() const {
  const std::string text = scalar_text();
  std::optional<double> value = parse_number(text);
  if (!value || *value <= 0.0) {
    fail("expected a positive number for '" + name_ + "', got '" + text + "'");
  }
  return *value;
}

double YamlValue::as_non_negative() const {
  const std::string text = scalar_text();
  std::optional<double> value = parse_number(text);
  if (!value || *value < 0.0) {
    fail("expected a non-negative number for '" + name_ + "', got '" + text + "'");
  }
  return *value;
}

int YamlValue::as_integer() const {
  const std::string text = scalar_text();
  std::optional<int> value = parse_integer(text);
  if (!value) fail("expected a whole number for '" + name_ + "', got '" + text + "'");
  return *value;
}

int YamlValue::as_positive_integer() const {
  const std::string text = scalar_text();
  std::optional<int> value = parse_integer(text);
  if (!value || *value < 1) {
    fail("expected a positive whole number for '" + name_ + "', got '" + text + "'");
  }
  return *value;
}

bool YamlValue::as_bool() const {
  const std::string text = scalar_text();
  if (text == "true") return true;
  if (text == "false") return false;
  fail("expected true or false for '" + name_ + "', got '" + text + "'");
}

Eigen::Vector3d YamlValue::as_vector3() const {
  if (!is_sequence() || node_.size() != 3) {
    std::string got = is_sequence() ? std::to_string(node_.size()) + " values"
                      : is_scalar() ? "'" + node_.Scalar() + "'"
                                    : std::string(is_map() ? "a map" : "nothing");
    fail("expected 3 numbers [x, y, z] for '" + name_ + "', got " + got);
  }
  Eigen::Vector3d vector;
  const std::vector<YamlValue> parts = items();
  for (int i = 0; i < 3; ++i) vector[i] = parts[i].as_number();
  return vector;
}

std::string YamlValue::as_choice(std::initializer_list<std::string_view> choices) const {
  const std::string text = scalar_text();
  for (std::string_view choice : choices) {
    if (choice == text) return text;
  }
  fail("expected one of " + join(choices) + " for '" + name_ + "', got '" + text + "'");
}

std::filesystem::path YamlValue::as_existing_file(std::string_view what) const {
  const std::string text = as_string();
  const std::filesystem::path path = std::filesystem::path(*file_).parent_path() / text;
  const std::string problem = regular_file_problem(path);
  if (!problem.empty()) {
    fail("expected " + std::string(what) + ", got '" + abbreviated(text) + "' (" + problem + ")");
  }
  return path;
}

YamlDocument::YamlDocument(YAML::Node root, std::shared_ptr<const std::string> file)
    : root_(std::move(root)), file_(std::move(file)) {}

YamlDocument YamlDocument::load_text(const std::string& text, const std::string& file) {
  auto name = std::make_shared<const std::string>(file);
  try {
    return YamlDocument(YAML::Load(text), name);
  } catch (const YAML::Exception& error) {
    // Syntax errors: yaml-cpp's own message, at its (0-based) mark.
    throw InputError("YAML syntax error: " + error.msg, location_of(error.mark, file));
  }
}

YamlDocument YamlDocument::load_file(const std::string& path) {
  std::ifstream stream(path, std::ios::binary);
  if (!stream) throw InputError("cannot open the case file '" + path + "'");
  std::ostringstream text;
  text << stream.rdbuf();
  return load_text(text.str(), path);
}

YamlValue YamlDocument::root() const { return YamlValue(root_, file_, "the case file"); }

}  // namespace limber::io
