// Free text (body and joint names, quantities) as part of a file name: the VTU files and mode
// animation folders of `limber render`, the images of `limber report`.
//
// Bytes of [A-Za-z0-9_-] stay; every other byte becomes "~XX" (two upper-case hex digits), so
// "R.1" -> "R~2E1", "arm/left" -> "arm~2Fleft"; the empty text is "~". The result is safe in a
// path and in a URL, never "." or "..", never hidden, and injective: every '~' starts an escape,
// so two names never share a file (results/link_name.h does the same for HDF5 links).
#pragma once

#include <string>
#include <string_view>

namespace limber::render {

std::string file_stem(std::string_view text);

}  // namespace limber::render
