#include "results/flexible_body_file.h"

#include <vector>

#include "core/error.h"
#include "results/beam_sections.h"
#include "results/results_layout.h"
#include "results/sample_series.h"
#include "results/writer_attributes.h"

namespace limber::results {

void write_mesh_and_modes(hid_t body_group, const FlexibleBodySpec& body) {
  const Eigen::Index nn = body.nodes.rows();
  const Eigen::Index nm = body.mode_translations.cols();
  // Mesh: nodes, ids, elements, tube radius.
  H5Handle mesh = create_group(body_group, layout::body::kMesh);
  const auto n = static_cast<hsize_t>(nn);
  write_dataset(mesh.get(), layout::mesh::kNodes, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, {n, 3}, body.nodes.data());
  std::vector<int> ids = body.node_ids;
  if (ids.empty()) {
    for (Eigen::Index i = 0; i < nn; ++i) ids.push_back(static_cast<int>(i) + 1);
  }
  write_dataset(mesh.get(), layout::mesh::kNodeIds, H5T_STD_I32LE, H5T_NATIVE_INT, {n}, ids.data());
  write_dataset(mesh.get(), layout::mesh::kLines, H5T_STD_I32LE, H5T_NATIVE_INT,
                {static_cast<hsize_t>(body.lines.rows()), 2}, body.lines.data());
  write_dataset(mesh.get(), layout::mesh::kQuads, H5T_STD_I32LE, H5T_NATIVE_INT,
                {static_cast<hsize_t>(body.quads.rows()), 4}, body.quads.data());
  write_dataset(mesh.get(), layout::mesh::kBeamRadius, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, {},
                &body.beam_radius);
  if (!body.beam_sections.empty()) {
    LIMBER_DEMAND(static_cast<Eigen::Index>(body.beam_sections.outline.size()) == body.lines.rows());
    check(try_write_beam_sections(mesh.get(), body.beam_sections) ? 0 : -1, "write the beam sections");
  }

  // Modes: column-major (3 nn) x nm is exactly the row-major [nm, nn, 3] layout.
  H5Handle modes = create_group(body_group, layout::body::kModes);
  const Eigen::MatrixXd translations =
      nm == 0 ? Eigen::MatrixXd(3 * nn, 0) : body.mode_translations;
  write_dataset(modes.get(), layout::modes::kTranslations, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE,
                {static_cast<hsize_t>(nm), n, 3}, translations.data());
  write_dataset(modes.get(), layout::modes::kFrequenciesHz, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE,
                {static_cast<hsize_t>(nm)}, body.frequencies_hz.data());
  if (!body.mode_kinds.empty()) {
    write_string_dataset(modes.get(), layout::modes::kKinds, body.mode_kinds);
    write_string_dataset(modes.get(), layout::modes::kLabels, body.mode_labels);
  }
}

}  // namespace limber::results
