// VTK XML UnstructuredGrid (.vtu) files written by hand (house style §5: the solver does
// not link VTK). Format: "VTK File Formats", VTK User's Guide 11th ed., §19.3
// (file version 1.0, little-endian, UInt32 headers). Lines (VTK_LINE = 3) and quads
// (VTK_QUAD = 9); point-data arrays of 1 or 3 components.
//
// Encodings: ASCII, or inline base64 "binary" where each array is the base64 encoding of
// one stream [UInt32 byte count][little-endian values].
#pragma once

#include <Eigen/Core>
#include <array>
#include <string>
#include <vector>

#include "fe/fe_model.h"
#include "modal/mode_set.h"

namespace limber::io {

enum class VtuEncoding { kAscii, kBase64 };

struct VtuPointArray {
  std::string name;
  Eigen::MatrixXd values;  // nn x (1 or 3), one row per point
};

struct VtuMesh {
  std::vector<Eigen::Vector3d> points;
  std::vector<std::array<int, 2>> lines;
  std::vector<std::array<int, 4>> quads;
  std::vector<int> point_ids;  // written as Int32 point data "node_id" when not empty
};

// Writes `path`. Preconditions: every array has points.size() rows; element indices are
// valid. Throws InputError when the file cannot be written.
void write_vtu(const std::string& path, const VtuMesh& mesh,
               const std::vector<VtuPointArray>& arrays, VtuEncoding encoding);

// One file per body: the FE mesh and every mode shape's translations as a 3-component
// point array named by mode_array_name. Precondition: shapes.rows() == model.dof_count().
void write_modes_vtu(const std::string& path, const fe::FeModel& model,
                     const modal::ModeSet& mode_set, VtuEncoding encoding);

// "mode_01_normal_123.4Hz": 1-based index (2 digits or more), kind, frequency [Hz].
std::string mode_array_name(int index, const modal::ModeInfo& mode);

// RFC 4648 base64 (with '=' padding) of `bytes`.
std::string base64_encode(const std::vector<unsigned char>& bytes);

}  // namespace limber::io
