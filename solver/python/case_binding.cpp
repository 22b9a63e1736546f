#include "python/case_binding.h"

#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <filesystem>
#include <string>
#include <variant>
#include <vector>

#include "python/dict_case_text.h"

namespace py = pybind11;

namespace limber::python {

namespace {

// How a case dict is named in the reader's messages; its errors are reported by key path.
constexpr const char* kDictName = "<dict>";

io::Case read_case_dict(const py::dict& case_dict) {
  const DictCaseText text = dict_case_text(case_dict);
  try {
    return io::read_case_text(text.text, kDictName);
  } catch (const InputError& error) {
    // Errors in a `base` file keep their file:line:col; those of the dict get its key path.
    if (error.where().file != kDictName) throw;
    throw KeyPathError(text.path_of(error.where().line), error.message());
  }
}

std::vector<std::string> body_names(const io::Case& input) {
  std::vector<std::string> names;
  if (!input.mechanism) return names;
  for (const io::BodyEntry& body : input.mechanism->bodies) {
    names.push_back(std::visit(
        [](const auto& entry) {
          if constexpr (std::is_same_v<std::decay_t<decltype(entry)>, io::RigidBodyEntry>) {
            return entry.spec.name;
          } else {
            return entry.name;
          }
        },
        body));
  }
  return names;
}

std::vector<std::string> joint_names(const io::Case& input) {
  std::vector<std::string> names;
  if (input.mechanism) {
    for (const io::JointEntry& joint : input.mechanism->joints) names.push_back(joint.name);
  }
  return names;
}

std::vector<std::string> flexible_body_names(const io::Case& input) {
  std::vector<std::string> names;
  for (const io::FlexibleBodyCase& body : input.flexible_bodies) names.push_back(body.name);
  return names;
}

}  // namespace

std::shared_ptr<const io::Case> case_of(const py::handle& case_or_path) {
  if (py::isinstance<PythonCase>(case_or_path)) return case_or_path.cast<const PythonCase&>().input;
  const std::filesystem::path path = case_or_path.cast<std::filesystem::path>();
  return std::make_shared<const io::Case>(io::read_case_file(path.string()));
}

void bind_case(py::module_& module) {
  static py::exception<InputError> case_error(module, "CaseError", PyExc_ValueError);
  case_error.doc() =
      "Bad input: a case file, a case dict or an argument limber cannot run.\n\n"
      "str(error) says what was expected and what was found, and where. Attributes:\n"
      "  file, line, column: the place in a case file (1-based; None when not in a file)\n"
      "  key_path: the place in a case dict, e.g. 'bodies.crank.mass' (None for files)\n"
      "A subclass of ValueError.";
  py::register_exception_translator([](std::exception_ptr thrown) {
    try {
      if (thrown) std::rethrow_exception(thrown);
    } catch (const InputError& error) {
      py::object raised = py::reinterpret_borrow<py::object>(case_error)(error.what());
      const auto* in_dict = dynamic_cast<const KeyPathError*>(&error);
      const bool located = !in_dict && error.where().known();
      raised.attr("file") = located ? py::cast(error.where().file) : py::none();
      raised.attr("line") = located && error.where().line > 0 ? py::cast(error.where().line) : py::none();
      raised.attr("column") = located && error.where().column > 0 ? py::cast(error.where().column) : py::none();
      raised.attr("key_path") = in_dict ? py::cast(in_dict->key_path()) : py::none();
      PyErr_SetObject(case_error.ptr(), raised.ptr());
    }
  });

  py::class_<PythonCase>(module, "Case",
                         "A case read and checked (docs/case-format.md): from limber.load_case or "
                         "limber.case_from_dict, for limber.run. Nothing is computed until a run.")
      .def_property_readonly("file", [](const PythonCase& c) { return c.input->file; },
                             "The case file's path as given ('<dict>' for a dict).")
      .def_property_readonly("title", [](const PythonCase& c) { return c.input->title; })
      .def_property_readonly("bodies", [](const PythonCase& c) { return body_names(*c.input); },
                             "Names of the mechanism's bodies, in file order.")
      .def_property_readonly("joints", [](const PythonCase& c) { return joint_names(*c.input); },
                             "Names of the mechanism's joints, in file order.")
      .def_property_readonly("flexible_bodies", [](const PythonCase& c) { return flexible_body_names(*c.input); },
                             "Names of the `flexible_bodies` entries (FE models and mode requests).")
      .def("__repr__", [](const PythonCase& c) { return "<limber.Case '" + c.input->title + "' from " + c.input->file + ">"; });

  module.def(
      "load_case",
      [](const std::filesystem::path& path) {
        return PythonCase{std::make_shared<const io::Case>(io::read_case_file(path.string()))};
      },
      py::arg("path"),
      "load_case(path) -> Case\n\n"
      "Reads and checks the case file at `path` (str or os.PathLike; YAML, docs/case-format.md)\n"
      "as `limber run` does. Raises CaseError at file:line:col (its attributes file, line,\n"
      "column) when the file is bad.");
  module.def(
      "case_from_dict",
      [](const py::dict& case_dict) { return PythonCase{std::make_shared<const io::Case>(read_case_dict(case_dict))}; },
      py::arg("d"),
      "case_from_dict(d) -> Case\n\n"
      "A case given as a dict with the sections and keys of a case file (docs/case-format.md):\n"
      "maps as dicts with str keys, lists (or tuples, numpy arrays), str, bool, int, float,\n"
      "None. It gets the checks a case file gets; a bad value raises CaseError naming its key\n"
      "path, e.g. 'bodies.crank.mass: expected a positive number ...' (attribute key_path).\n"
      "Relative file names in it (`base`, bulk-data decks) are relative to the current folder.\n"
      "e.g. d = yaml.safe_load(open('cases/slider_crank.yaml')); d['run']['t_end'] = 0.1");
}

}  // namespace limber::python
