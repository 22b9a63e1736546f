// Names in input files (bodies, markers, joints, drivers, forces, flexible bodies) are free
// text: any characters, UTF-8 included, except control characters (bytes 0x00-0x1F and 0x7F:
// NUL, tab, newline, ...). Those are not text: a NUL ends a name early in every C string, HDF5
// included, and the others do not show in messages, plots or file names. How names become
// HDF5 link names and file names: results/link_name.h.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

#include "core/error.h"

namespace limber {

// The longest name, in bytes. Names are kept in HDF5 attributes (at most 64 KiB each in the
// 1.8 file format results.h5 and modes.h5 use) and shown in messages and plots.
inline constexpr std::size_t kMaxNameBytes = 256;

// Checks a name read from an input file. `what` names its kind ("body", "marker", ...).
// Throws InputError at `where`, e.g.
//   `body name: expected a non-empty name, got ""`,
//   `body name: expected at most 256 bytes, got "arm_arm_arm_…… (4000 bytes)"` (core/input_file.h),
//   `body name: expected text without control characters, got "a\x00b" (byte 0x00 at 2)`.
void check_name_text(std::string_view what, std::string_view name, const SourceLocation& where);

// The name with control characters shown as \xHH, for messages.
std::string printable_name(std::string_view name);

}  // namespace limber
