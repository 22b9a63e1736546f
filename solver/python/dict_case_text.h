// A case given as a Python dict (limber.case_from_dict) written as YAML text for the case
// reader (io/case_reader.h), so that a dict gets exactly the checks a case file gets. The text
// is flow style with one entry per line ("{", then `"key": value,` lines), so the line of any
// value the reader reports names one key path ("bodies.crank.mass", "joints.R1.position[2]"),
// and a map's own errors (a missing key) its path too: a flow map starts on its key's line.
#pragma once

#include <pybind11/pybind11.h>

#include <string>
#include <vector>

#include "core/error.h"

namespace limber::python {

// Bad input in a case dict: what() is "<key path>: <message>" (the path "" for the dict itself).
class KeyPathError : public InputError {
 public:
  KeyPathError(const std::string& key_path, const std::string& message)
      : InputError(key_path.empty() ? message : key_path + ": " + message), key_path_(key_path) {}
  const std::string& key_path() const { return key_path_; }

 private:
  std::string key_path_;
};

struct DictCaseText {
  std::string text;
  std::vector<std::string> line_paths;  // the key path of each line, line 1 at index 0

  // The key path of 1-based `line`; "" when out of range or at the root.
  std::string path_of(int line) const;
};

// Writes `case_dict`: maps with string keys, sequences (list, tuple, any iterable but str
// and bytes, numpy arrays included), str, bool, int, float and None. Throws KeyPathError for
// any other value.
DictCaseText dict_case_text(const pybind11::handle& case_dict);

}  // namespace limber::python
