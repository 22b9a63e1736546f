// limber.Case, limber.load_case, limber.case_from_dict and limber.CaseError: a case read and
// checked by the case reader (io/case_reader.h), from a file or from a Python dict.
#pragma once

#include <pybind11/pybind11.h>

#include <memory>

#include "io/case_reader.h"

namespace limber::python {

// A case as read: the reader's data, shared by every run that uses it.
struct PythonCase {
  std::shared_ptr<const io::Case> input;
};

// Adds Case, load_case, case_from_dict and CaseError to `module`, and turns every InputError
// into CaseError.
void bind_case(pybind11::module_& module);

// `case_or_path` as a case: a limber.Case as it is, a path (str or os.PathLike) read.
std::shared_ptr<const io::Case> case_of(const pybind11::handle& case_or_path);

}  // namespace limber::python
