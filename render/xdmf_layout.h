// Paths, shapes and units of DIR/vtk/scene.h5, the heavy data of the ParaView scene
// DIR/vtk/scene.xmf (render/xdmf_export.h, docs/rendering.md). The writer and the tests spell a
// name only here.
//
// One group per body, per sample one group of nodal data: every dataset a grid reads at one
// time is whole (ParaView 5.11's two XDMF readers agree on no hyperslab syntax: its "XDMF
// Reader" takes the XDMF 2 HyperSlab item, on which its "Xdmf3ReaderS" crashes).
// ns: samples in [t0, t1]; np: points of the body's grid; nc: its cells; nt: entries of its
// topology. Units SI; vectors in ground axes.
#pragma once

#include <cstdio>
#include <string>
#include <string_view>

namespace limber::render::xdmf {

inline constexpr const char* kFileName = "scene.h5";
inline constexpr const char* kDescriptionName = "scene.xmf";
inline constexpr const char* kScriptName = "open_in_paraview.py";

// Root attributes.
inline constexpr const char* kFormatAttribute = "format";  // string kFormat
inline constexpr const char* kFormat = "limber-paraview-scene";
inline constexpr const char* kVersionAttribute = "version";  // int kVersion
inline constexpr int kVersion = 1;

// float64 [ns]: sample times [s] (results.h5 /time inside [t0, t1]).
inline constexpr const char* kTime = "/time";
// int32 [ns]: each sample's row in results.h5.
inline constexpr const char* kSampleRows = "/sample_rows";

// /bodies/<body>/ (link name as results.h5's, results/link_name.h): attributes name (the
// case's, results::kNameAttribute), kind and cells.
inline constexpr const char* kBodies = "/bodies";
namespace body {
inline constexpr const char* kKindAttribute = "kind";  // "rigid" | "flexible"
inline constexpr const char* kTopology = "topology";  // int32 [nt], XDMF Mixed (below)
inline constexpr const char* kCellCountAttribute = "cells";  // int, nc
// float64 [nc] [m]: the beam's section radius on line cells (results.h5 mesh/beam_radius),
// 0 on surface cells.
inline constexpr const char* kBeamRadius = "beam_radius";
// Rigid bodies: float64 [np, 3] and [np] zeros, the displacements of every sample.
inline constexpr const char* kZeroVectors = "zero_vectors";
inline constexpr const char* kZeroScalars = "zero_scalars";
inline constexpr const char* kSamples = "samples";  // group of samples, named sample_name(k)
}  // namespace body

// /bodies/<body>/samples/<k>/: the body at sample k (0-based in /time).
namespace sample {
inline constexpr const char* kPoints = "points";  // float64 [np, 3]: p + R X0 [m]
// Flexible bodies: float64 [np, 3] R u, elastic displacement [m], and [np] |u| [m].
inline constexpr const char* kDisplacement = "displacement";
inline constexpr const char* kDisplacementMagnitude = "displacement_magnitude";
// Flexible bodies: float64 [np, 3] R u_rel, the elastic displacement relative to the rigid fit
// through the body's joint nodes (render/relative_deflection.h) [m], and [np] |u_rel| [m].
inline constexpr const char* kRelativeDeflection = "relative_deflection";
inline constexpr const char* kRelativeDeflectionMagnitude = "relative_deflection_magnitude";
// Flexible bodies with stress output: float64 [nc], equivalent stress per cell [Pa] (NaN:
// element not recorded), the history row at or before the sample.
inline constexpr const char* kStress = "stress";
}  // namespace sample

// XDMF Mixed topology codes: each cell is its code, then (polygon and polyline only) its point
// count, then its point indices.
inline constexpr int kPolyline = 2;
inline constexpr int kPolygon = 3;
inline constexpr int kTriangle = 4;
inline constexpr int kQuadrilateral = 5;

// "00042": the link name of sample k.
inline std::string sample_name(long k) {
  char text[32];
  std::snprintf(text, sizeof text, "%05ld", k);
  return text;
}

// `group` + "/" + `name`.
inline std::string at(std::string_view group, std::string_view name) {
  std::string path(group);
  path += '/';
  path += name;
  return path;
}

}  // namespace limber::render::xdmf
