#include "python/dict_case_text.h"

#include <yaml-cpp/yaml.h>

namespace py = pybind11;

namespace limber::python {

namespace {

class Writer {
 public:
  DictCaseText result;

  // Writes `value` at the end of the current line, which belongs to `path`.
  void value(const py::handle& value, const std::string& path) {
    if (value.is_none()) {
      result.text += "null";
    } else if (py::isinstance<py::bool_>(value)) {
      result.text += value.cast<bool>() ? "true" : "false";
    } else if (py::isinstance<py::str>(value)) {
      YAML::Emitter quoted;
      quoted << YAML::DoubleQuoted << value.cast<std::string>();
      result.text += quoted.c_str();
    } else if (py::isinstance<py::dict>(value)) {
      map(py::reinterpret_borrow<py::dict>(value), path);
    } else if (py::isinstance<py::bytes>(value)) {
      refuse(value, path);
    } else if (py::isinstance<py::iterable>(value)) {  // list, tuple, numpy array (before its __index__)
      sequence(py::reinterpret_borrow<py::iterable>(value), path);
    } else if (PyIndex_Check(value.ptr())) {  // int, numpy integers
      result.text += py::str(py::int_(py::reinterpret_borrow<py::object>(value))).cast<std::string>();
    } else if (PyFloat_Check(value.ptr()) || py::hasattr(value, "__float__")) {  // float, numpy reals
      // repr round-trips; inf and nan come out as names the reader refuses with this path.
      result.text += py::repr(py::float_(py::reinterpret_borrow<py::object>(value))).cast<std::string>();
    } else {
      refuse(value, path);
    }
  }

 private:
  [[noreturn]] static void refuse(const py::handle& value, const std::string& path) {
    throw KeyPathError(path, "expected a number, text, list or dict, got " + py::repr(value).cast<std::string>());
  }

  void new_line(const std::string& path) {
    result.text += '\n';
    result.line_paths.push_back(path);
  }

  void map(const py::dict& entries, const std::string& path) {
    result.text += '{';
    bool first = true;
    for (const auto& [key, item] : entries) {
      if (!py::isinstance<py::str>(key)) {
        throw KeyPathError(path, "expected text keys, got " + py::repr(key).cast<std::string>());
      }
      const std::string name = key.cast<std::string>();
      const std::string item_path = path.empty() ? name : path + "." + name;
      if (!first) result.text += ',';
      first = false;
      new_line(item_path);
      YAML::Emitter quoted;
      quoted << YAML::DoubleQuoted << name;
      result.text += quoted.c_str();
      result.text += ": ";
      value(item, item_path);
    }
    new_line(path);
    result.text += '}';
  }

  void sequence(const py::iterable& items, const std::string& path) {
    result.text += '[';
    int index = 0;
    for (const py::handle item : items) {
      const std::string item_path = path + "[" + std::to_string(index) + "]";
      if (index++ > 0) result.text += ',';
      new_line(item_path);
      value(item, item_path);
    }
    new_line(path);
    result.text += ']';
  }
};

}  // namespace

std::string DictCaseText::path_of(int line) const {
  if (line < 1 || line > static_cast<int>(line_paths.size())) return "";
  return line_paths[static_cast<std::size_t>(line - 1)];
}

DictCaseText dict_case_text(const py::handle& case_dict) {
  if (!py::isinstance<py::dict>(case_dict)) {
    throw KeyPathError("", "expected a dict of case sections, got " + py::repr(case_dict).cast<std::string>());
  }
  Writer writer;
  writer.result.line_paths.push_back("");  // line 1: the root's "{"
  writer.value(case_dict, "");
  writer.result.text += '\n';
  return writer.result;
}

}  // namespace limber::python
