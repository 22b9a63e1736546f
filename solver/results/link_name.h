// Free-text names (of bodies, joints, drivers, hinge limits, energies, flexible bodies) as HDF5
// link names, in results.h5 and modes.h5 alike (docs/results-format.md, "Names").
//
// HDF5 splits paths at '/', ends C strings at NUL and reads "." as the group itself, so a name
// cannot always be a link name as it is. link_name() percent-encodes the bytes that cannot stand
// or would be ambiguous: '%', '/', control characters (0x00-0x1F, 0x7F) and a leading '.'
// become "%XX" (two upper-case hex digits); every other byte, UTF-8 included, stays as it is.
// Names of letters, digits, '_', '-', ' ' and inner '.' (all names in cases/) map to themselves.
//
// The mapping is injective: every '%' of a link name starts an escape, so reading escapes back
// gives the name; two names never share a link. The writers store the original name too, in
// the string attribute `name` (kNameAttribute) of the group or dataset; readers show that
// attribute (files written before it existed: the link name) and build paths from the link.
#pragma once

#include <string>
#include <string_view>

namespace limber::results {

// The link name of `name`. Precondition: name is not empty (case names are checked on input,
// core/names.h); aborts otherwise.
std::string link_name(std::string_view name);

// The attribute holding a link's original name.
inline constexpr const char* kNameAttribute = "name";

}  // namespace limber::results
