// The one writer of modes.h5 (docs/modes-format.md), beside its one reader (modes_reader.h):
// it writes the same plain values the reader returns with ModesContent::kAll, so that a file
// written and read back gives the values written.
#pragma once

#include "results/modes_reader.h"

#include <filesystem>

namespace limber::results {

// Writes `data` to `path` (truncating it); `data.file` is not used. Every body needs its mesh,
// modes and kAll fields filled: mesh.mode_translations (3 nn) x nm, nm mode records, shapes
// dof_count x nm, modal_stiffness nm, and the invariants for nm modes. Throws InputError naming
// the file and object when HDF5 cannot write it.
void write_modes(const std::filesystem::path& path, const ModesData& data);

}  // namespace limber::results
