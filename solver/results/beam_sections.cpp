#include "results/beam_sections.h"

#include <cmath>

#include "core/error.h"
#include "results/h5_reader.h"
#include "results/h5_write.h"
#include "results/results_layout.h"

namespace limber::results {

bool try_write_beam_sections(hid_t mesh, const BeamSections& s) {
  namespace m = layout::mesh;
  const auto nl = static_cast<hsize_t>(s.outline.size());
  const auto no = static_cast<hsize_t>(s.hollow.size());
  LIMBER_DEMAND(static_cast<hsize_t>(s.y_axes.rows()) == nl && s.equivalent.size() == no &&
                s.offsets.size() == no + 1 && s.offsets.back() == s.points.rows());
  return try_write_dataset(mesh, m::kBeamYAxes, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, {nl, 3},
                           s.y_axes.data()) &&
         try_write_dataset(mesh, m::kBeamOutline, H5T_STD_I32LE, H5T_NATIVE_INT, {nl},
                           s.outline.data()) &&
         try_write_dataset(mesh, m::kOutlinePoints, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE,
                           {static_cast<hsize_t>(s.points.rows()), 2}, s.points.data()) &&
         try_write_dataset(mesh, m::kOutlineOffsets, H5T_STD_I32LE, H5T_NATIVE_INT, {no + 1},
                           s.offsets.data()) &&
         try_write_dataset(mesh, m::kOutlineHollow, H5T_STD_I8LE, H5T_NATIVE_INT8, {no},
                           s.hollow.data()) &&
         try_write_dataset(mesh, m::kOutlineEquivalent, H5T_STD_I8LE, H5T_NATIVE_INT8, {no},
                           s.equivalent.data());
}

BeamSections read_beam_sections(const H5Reader& r, const std::string& mesh, long line_count) {
  namespace m = layout::mesh;
  BeamSections sections;
  const std::string axes_path = layout::at(mesh, m::kBeamYAxes);
  if (!r.exists(axes_path)) return sections;  // older file: beams drawn as tubes
  const auto nl = static_cast<hsize_t>(line_count);

  // Per beam: its y axis and outline index.
  if (r.rows(axes_path, 3) != nl) r.fail(axes_path + " with one row per line", "another count");
  const std::vector<double> axes = r.read<double>(axes_path, H5T_NATIVE_DOUBLE, nl);
  sections.y_axes = Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>>(
      axes.data(), line_count, 3);
  const std::string outline_path = layout::at(mesh, m::kBeamOutline);
  if (r.rows(outline_path, 0) != nl) r.fail(outline_path + " with one value per line", "another count");
  sections.outline = r.read<int>(outline_path, H5T_NATIVE_INT, nl);

  // The outline table.
  const std::string offsets_path = layout::at(mesh, m::kOutlineOffsets);
  const hsize_t no1 = r.rows(offsets_path, 0);
  sections.offsets = r.read<int>(offsets_path, H5T_NATIVE_INT, no1);
  const std::string points_path = layout::at(mesh, m::kOutlinePoints);
  const hsize_t np = r.rows(points_path, 2);
  const std::vector<double> points = r.read<double>(points_path, H5T_NATIVE_DOUBLE, np);
  sections.points = Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, 2, Eigen::RowMajor>>(
      points.data(), static_cast<Eigen::Index>(np), 2);
  const hsize_t no = no1 == 0 ? 0 : no1 - 1;
  for (const char* name : {m::kOutlineHollow, m::kOutlineEquivalent}) {
    const std::string path = layout::at(mesh, name);
    if (r.rows(path, 0) != no) r.fail(path + " with one value per outline", "another count");
  }
  sections.hollow = r.read<std::int8_t>(layout::at(mesh, m::kOutlineHollow), H5T_NATIVE_INT8, no);
  sections.equivalent =
      r.read<std::int8_t>(layout::at(mesh, m::kOutlineEquivalent), H5T_NATIVE_INT8, no);

  // Consistency: offsets rising from 0 to np, polygons of 3 points or more, indices in range.
  if (no == 0 || sections.offsets.front() != 0 || sections.offsets.back() != static_cast<int>(np)) {
    r.fail(offsets_path + " rising from 0 to the " + std::to_string(np) + " outline points",
           "other values");
  }
  for (hsize_t k = 0; k < no; ++k) {
    const int count = sections.offsets[k + 1] - sections.offsets[k];
    const bool ok = sections.hollow[k] ? count >= 6 && count % 2 == 0 : count >= 3;
    if (!ok) {
      r.fail(offsets_path + " giving outline " + std::to_string(k) +
                 " at least 3 points per polygon (an even count when hollow)",
             std::to_string(count) + " points");
    }
  }
  for (std::size_t e = 0; e < sections.outline.size(); ++e) {
    if (sections.outline[e] < 0 || sections.outline[e] >= static_cast<int>(no)) {
      r.fail(outline_path + " values in 0.." + std::to_string(no - 1),
             std::to_string(sections.outline[e]) + " at line " + std::to_string(e));
    }
    if (!(std::abs(sections.y_axes.row(static_cast<Eigen::Index>(e)).norm() - 1.0) < 1e-6)) {
      r.fail(axes_path + " rows of unit length", "another length at line " + std::to_string(e));
    }
  }
  if (!sections.points.allFinite()) r.fail(points_path + " of finite values", "NaN or infinity");
  return sections;
}

}  // namespace limber::results
