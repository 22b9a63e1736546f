// The XDMF 2 text of DIR/vtk/scene.xmf over scene.h5 (render/xdmf_layout.h): a Temporal
// collection of the samples, each a Spatial collection of one Uniform grid per body with a
// Mixed topology, XYZ geometry and the point and cell attributes the body has. Every DataItem
// names a whole dataset, which both of ParaView 5.11's XDMF readers read.
#pragma once

#include <string>
#include <vector>

namespace limber::render {

// One grid of each sample. A further grid per body (e.g. beam solids as surface cells) is one
// more entry, with its own group holding its topology and per-sample points.
struct XdmfBody {
  std::string name;        // the case's name (the grid's name)
  std::string group;       // its group in scene.h5, e.g. "/bodies/crank"
  bool flexible = false;
  bool stress = false;     // cell data "stress" present
  long points = 0, cells = 0, topology = 0;  // np, nc, nt
};

// The description of `bodies` at `times` [s] (sample k's data under <group>/samples/<k>).
std::string xdmf_description(const std::vector<XdmfBody>& bodies, const std::vector<double>& times);

}  // namespace limber::render
