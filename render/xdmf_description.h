// The XDMF 2 text of DIR/vtk/scene.xmf over scene.h5 (render/xdmf_layout.h): a Temporal
// collection of one Uniform grid per sample, all bodies in it, with a Mixed topology, XYZ
// geometry and the point and cell attributes. Every DataItem names a whole dataset, which both
// of ParaView 5.11's XDMF readers read. About 2 kB per sample, whatever the number of bodies.
#pragma once

#include <string>
#include <vector>

namespace limber::render {

// The grid every sample shares the shape of.
struct XdmfGrid {
  long points = 0, cells = 0, topology = 0;  // np, nc, nt
  bool stress = false;                       // cell data "stress" present
  std::vector<std::string> body_names;       // the value k of cell data `body` is body_names[k]
};

// The description of `grid` at `times` [s] (sample k's data under /samples/<k>); no grid at
// all when it has no points. Each body's name is an Information element of the domain, "body k"
// = its name, so that a reader of the file knows which value of `body` to pick.
std::string xdmf_description(const XdmfGrid& grid, const std::vector<double>& times);

}  // namespace limber::render
