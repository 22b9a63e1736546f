#include "io/modes_file.h"

#include "core/error.h"
#include "modal/modal_stress.h"
#include "results/modes_writer.h"

namespace limber::io {

namespace {

std::vector<results::ModeRecord> mode_records(const std::vector<modal::ModeInfo>& modes) {
  std::vector<results::ModeRecord> records;
  for (const modal::ModeInfo& mode : modes) {
    records.push_back({modal::to_string(mode.kind), mode.frequency_hz, mode.label});
  }
  return records;
}

results::MeshData mesh_data(const fe::FeModel& model, const Eigen::MatrixXd& shapes) {
  results::MeshData mesh;
  mesh.nodes.resize(model.node_count(), 3);
  for (int node = 0; node < model.node_count(); ++node) {
    mesh.nodes.row(node) = model.node_positions[node].transpose();
  }
  mesh.node_ids = model.node_ids;
  mesh.lines.resize(static_cast<Eigen::Index>(model.beams.size()), 2);
  for (std::size_t e = 0; e < model.beams.size(); ++e) {
    mesh.lines.row(e) << model.beams[e].nodes[0], model.beams[e].nodes[1];
  }
  // Triangles as quads with the last node repeated (docs/modes-format.md).
  mesh.quads.resize(static_cast<Eigen::Index>(model.shells.size() + model.triangles.size()), 4);
  Eigen::Index row = 0;
  for (const fe::ShellElement& shell : model.shells) {
    mesh.quads.row(row++) << shell.nodes[0], shell.nodes[1], shell.nodes[2], shell.nodes[3];
  }
  for (const fe::ShellTriangle& t : model.triangles) {
    mesh.quads.row(row++) << t.nodes[0], t.nodes[1], t.nodes[2], t.nodes[2];
  }
  mesh.mode_translations.resize(3 * model.node_count(), shapes.cols());
  for (Eigen::Index i = 0; i < shapes.cols(); ++i) {
    const Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor> t =
        mode_translations(shapes, static_cast<int>(i));
    mesh.mode_translations.col(i) = Eigen::Map<const Eigen::VectorXd>(t.data(), t.size());
  }
  return mesh;
}

results::InvariantsData invariants_data(const modal::ModalInvariants& inv) {
  results::InvariantsData data;
  data.mass = inv.mass;
  data.first_moment = inv.first_moment;
  data.inertia = inv.inertia;
  data.translation_coupling = inv.translation_coupling;
  data.rotation_coupling = inv.rotation_coupling;
  data.inertia_first_order = {inv.inertia_first_order.begin(), inv.inertia_first_order.end()};
  data.inertia_second_order = {inv.inertia_second_order.begin(), inv.inertia_second_order.end()};
  data.rotation_coupling_first_order = {inv.rotation_coupling_first_order.begin(),
                                        inv.rotation_coupling_first_order.end()};
  return data;
}

results::ModesBody modes_body(const BodyModesRef& body) {
  LIMBER_DEMAND(body.model != nullptr && body.mode_set != nullptr);
  const fe::FeModel& model = *body.model;
  const modal::ModeSet& set = *body.mode_set;
  results::ModesBody out;
  out.name = body.name;
  out.mesh = mesh_data(model, set.shapes);
  out.modes = mode_records(set.modes);
  out.mesh.frequencies_hz.resize(static_cast<Eigen::Index>(set.modes.size()));
  for (std::size_t i = 0; i < set.modes.size(); ++i) {
    out.mesh.frequencies_hz(i) = set.modes[i].frequency_hz;
  }
  out.dof_count = model.dof_count();
  out.fixed.resize(static_cast<Eigen::Index>(model.fixed_dofs.size()), 2);
  for (std::size_t i = 0; i < model.fixed_dofs.size(); ++i) {
    out.fixed.row(i) << model.fixed_dofs[i].node, static_cast<int>(model.fixed_dofs[i].dof);
  }
  out.shapes = set.shapes;
  out.modal_stiffness = set.modal_stiffness;
  out.rigid_modes = mode_records(set.rigid_modes);
  out.invariants = invariants_data(set.invariants);
  // Modal stresses: element resultants per unit modal coordinate (docs/stress-recovery.md).
  const modal::ModalStress stress = modal::modal_stress(model, set.shapes);
  out.beam_stress_modal = stress.beam_modal;
  out.shell_stress_modal = stress.shell_modal;
  return out;
}

}  // namespace

Eigen::MatrixX3d mode_translations(const Eigen::MatrixXd& shapes, int mode) {
  const Eigen::Index nn = shapes.rows() / fe::kDofsPerNode;
  Eigen::MatrixX3d t(nn, 3);
  for (Eigen::Index node = 0; node < nn; ++node) {
    t.row(node) = shapes.col(mode).segment<3>(fe::kDofsPerNode * node).transpose();
  }
  return t;
}

void write_modes_file(const std::string& path, const std::string& title,
                      const std::string& case_file, const std::vector<BodyModesRef>& bodies) {
  results::ModesData data;
  data.title = title;
  data.case_file = case_file;
  for (const BodyModesRef& body : bodies) data.bodies.push_back(modes_body(body));
  results::write_modes(path, data);
}

}  // namespace limber::io
