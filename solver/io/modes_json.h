// The mode sets of a case as the JSON document `limber modes --json` prints and Python's
// `limber.modes` returns: {"bodies": {<name>: {"dofs": N, "modes": [{"kind", "frequency_hz",
// "label"}]}}, "failures": [...]}, rigid modes first; "failures" only when a body failed.
#pragma once

#include <string>
#include <vector>

#include "io/modes_file.h"

namespace limber::io {

std::string modes_json(const std::vector<BodyModesRef>& bodies, const std::vector<std::string>& failures);

}  // namespace limber::io
