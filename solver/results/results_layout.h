// Paths of results.h5 (docs/results-format.md) that its writer and its readers (render's
// results reader, and through it the report) share, so a name is spelled in one place.
// Only the joint markers' datasets are here so far; the older paths are still spelled in
// results_writer.cpp and render/results_reader.cpp.
#pragma once

namespace limber::results::layout {

// /joints/<joint>/marker_i and /joints/<joint>/marker_j: the joint's two markers, each a group
// with the attribute `name` (the marker's name in the case; absent when the writer was not
// given one) and two per-sample datasets.
inline constexpr const char* kMarkerGroups[2] = {"marker_i", "marker_j"};
// float64 [ns, 3]: the marker's origin in ground [m].
inline constexpr const char* kMarkerPosition = "position";
// float64 [ns, 4]: unit quaternion (w, x, y, z) rotating the marker's axes into ground; on a
// flexible body it carries the node's small elastic rotation.
inline constexpr const char* kMarkerOrientation = "orientation";

}  // namespace limber::results::layout
