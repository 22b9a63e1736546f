// Paths, shapes and units of DIR/vtk/scene.h5, the heavy data of the ParaView scene
// DIR/vtk/scene.xmf (render/xdmf_export.h, docs/rendering.md). The writer and the tests spell a
// name only here.
//
// All bodies form one grid: their points and cells one after the other in body order (results.h5
// order), the cell data `body` telling them apart. So each sample is one grid of the XDMF
// description, a few lines of XML (issue 28: one grid per body and sample made 44.5 MB of XML for
// the satellite). Per sample one group of nodal data: every dataset a grid reads at one time is
// whole (ParaView 5.11's two XDMF readers agree on no hyperslab syntax: its "XDMF Reader" takes
// the XDMF 2 HyperSlab item, on which its "Xdmf3ReaderS" crashes).
// ns: samples in [t0, t1]; np: points of the grid; nc: its cells; nt: entries of its topology.
// Units SI; vectors in ground axes.
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
inline constexpr int kVersion = 2;  // 1: one grid per body

// float64 [ns]: sample times [s] (results.h5 /time inside [t0, t1]).
inline constexpr const char* kTime = "/time";
// int32 [ns]: each sample's row in results.h5.
inline constexpr const char* kSampleRows = "/sample_rows";

// The grid's constant parts.
inline constexpr const char* kTopology = "/topology";  // int32 [nt], XDMF Mixed (below)
// float64 [nc] [m]: the beam's section radius on line cells (results.h5 mesh/beam_radius), 0 on
// surface cells.
inline constexpr const char* kBeamRadius = "/beam_radius";
// int32 [nc]: the body of each cell, its index in results.h5's body order (attribute `index`).
inline constexpr const char* kBody = "/body";

// /bodies/<body>/ (link name as results.h5's, results/link_name.h): a group of attributes only,
// where the body lies in the grid.
inline constexpr const char* kBodies = "/bodies";
namespace body {
inline constexpr const char* kKindAttribute = "kind";  // "rigid" | "flexible"
inline constexpr const char* kIndexAttribute = "index";  // int: its value of cell data `body`
inline constexpr const char* kFirstPointAttribute = "first_point";  // int
inline constexpr const char* kPointCountAttribute = "points";       // int
inline constexpr const char* kFirstCellAttribute = "first_cell";    // int
inline constexpr const char* kCellCountAttribute = "cells";         // int
}  // namespace body

// /samples/<k>/: the grid at sample k (0-based in /time), named sample_name(k).
inline constexpr const char* kSamples = "/samples";
namespace sample {
inline constexpr const char* kPoints = "points";  // float64 [np, 3]: p + R X0 [m]
// float64 [np, 3] R u, elastic displacement [m], and [np] |u| [m]; 0 on rigid bodies.
inline constexpr const char* kDisplacement = "displacement";
inline constexpr const char* kDisplacementMagnitude = "displacement_magnitude";
// float64 [np, 3] R u_rel, the elastic displacement relative to the rigid fit through the body's
// joint nodes (render/relative_deflection.h) [m], and [np] |u_rel| [m]; 0 on rigid bodies.
inline constexpr const char* kRelativeDeflection = "relative_deflection";
inline constexpr const char* kRelativeDeflectionMagnitude = "relative_deflection_magnitude";
// When some body has stress output: float64 [nc], equivalent stress per cell [Pa], the history
// row at or before the sample; NaN on cells of other bodies and elements not recorded.
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

// The dataset `name` of sample k.
inline std::string sample_path(long k, std::string_view name) { return at(at(kSamples, sample_name(k)), name); }

}  // namespace limber::render::xdmf
