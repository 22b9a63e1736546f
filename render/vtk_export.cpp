#include "vtk_export.h"

#include "beam_solids.h"
#include "body_pose.h"
#include "core/markup_escape.h"
#include "file_stem.h"
#include "primitive_source.h"
#include "stress_reader.h"
#include "results/file_names.h"

#include <vtkAppendFilter.h>
#include <vtkCellType.h>
#include <vtkDoubleArray.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkCellData.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkSmartPointer.h>
#include <vtkTransform.h>
#include <vtkTransformPolyDataFilter.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include <cstdio>
#include <fstream>
#include <iomanip>
#include <optional>
#include <stdexcept>

namespace limber::render {
namespace {

void add_vector_data(vtkUnstructuredGrid* grid, const RowMatrix3d& u_W) {
  vtkNew<vtkDoubleArray> displacement;
  displacement->SetName("displacement");
  displacement->SetNumberOfComponents(3);
  displacement->SetNumberOfTuples(u_W.rows());
  vtkNew<vtkDoubleArray> magnitude;
  magnitude->SetName("displacement_magnitude");
  magnitude->SetNumberOfTuples(u_W.rows());
  for (Eigen::Index k = 0; k < u_W.rows(); ++k) {
    displacement->SetTuple3(k, u_W(k, 0), u_W(k, 1), u_W(k, 2));
    magnitude->SetValue(k, u_W.row(k).norm());
  }
  grid->GetPointData()->AddArray(displacement);
  grid->GetPointData()->AddArray(magnitude);
  grid->GetPointData()->SetActiveVectors("displacement");
}

// The mesh of a flexible body at one sample (see header), with its beams' swept surface
// `solids` (beam_solids.h; empty for files without sections) after the nodes and elements.
vtkSmartPointer<vtkUnstructuredGrid> flexible_grid(const BodyTrack& body, const BodyState& state,
                                                   const BeamSolids& solids) {
  const Eigen::Matrix3d R = state.orientation.toRotationMatrix();
  const Eigen::Index nn = body.mesh.nodes.rows(), ns = solids.points_B.rows();
  // Surface points follow their nodes: the same reference placement and displacement.
  RowMatrix3d X_B(nn + ns, 3);
  X_B.topRows(nn) = body.mesh.nodes;
  X_B.bottomRows(ns) = solids.points_B;
  const RowMatrix3d x_W = (X_B * R.transpose()).rowwise() + state.position.transpose();
  const RowMatrix3d u_node_W = elastic_displacements(body.mesh, state) * R.transpose();
  RowMatrix3d u_W(nn + ns, 3);
  u_W.topRows(nn) = u_node_W;
  for (Eigen::Index k = 0; k < ns; ++k) {
    u_W.row(nn + k) = u_node_W.row(solids.node[static_cast<std::size_t>(k)]);
  }
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(x_W.rows());
  for (Eigen::Index k = 0; k < x_W.rows(); ++k) points->SetPoint(k, x_W(k, 0), x_W(k, 1), x_W(k, 2));
  grid->SetPoints(points);
  grid->Allocate(body.mesh.quads.rows() + body.mesh.lines.rows());
  for (Eigen::Index e = 0; e < body.mesh.quads.rows(); ++e) {
    const vtkIdType ids[4] = {body.mesh.quads(e, 0), body.mesh.quads(e, 1), body.mesh.quads(e, 2),
                              body.mesh.quads(e, 3)};
    grid->InsertNextCell(VTK_QUAD, 4, ids);
  }
  for (Eigen::Index e = 0; e < body.mesh.lines.rows(); ++e) {
    const vtkIdType ids[2] = {body.mesh.lines(e, 0), body.mesh.lines(e, 1)};
    grid->InsertNextCell(VTK_LINE, 2, ids);
  }
  std::vector<vtkIdType> ids;
  for (int c = 0; c < solids.cell_count(); ++c) {
    ids.clear();
    for (int i = solids.cell_offsets[c]; i < solids.cell_offsets[c + 1]; ++i) {
      ids.push_back(nn + solids.connectivity[i]);
    }
    const int type = ids.size() == 3 ? VTK_TRIANGLE : ids.size() == 4 ? VTK_QUAD : VTK_POLYGON;
    grid->InsertNextCell(type, static_cast<vtkIdType>(ids.size()), ids.data());
  }
  // beam_index: the line of each line cell and surface cell, -1 for shells.
  vtkNew<vtkIntArray> beam_index;
  beam_index->SetName("beam_index");
  beam_index->SetNumberOfTuples(grid->GetNumberOfCells());
  vtkIdType cell = 0;
  for (Eigen::Index q = 0; q < body.mesh.quads.rows(); ++q) beam_index->SetValue(cell++, -1);
  for (Eigen::Index e = 0; e < body.mesh.lines.rows(); ++e) beam_index->SetValue(cell++, static_cast<int>(e));
  for (int b : solids.beam) beam_index->SetValue(cell++, b);
  grid->GetCellData()->AddArray(beam_index);
  add_vector_data(grid, u_W);
  return grid;
}

// Cell data "stress" [Pa]; cells are the quads, then the lines, then the beams' surface cells
// (flexible_grid), elements of the stress history the lines, then the quads.
void add_stress_data(vtkUnstructuredGrid* grid, const BodyTrack& body, const StressTrack& stress,
                     double t, const BeamSolids& solids) {
  const auto lines = static_cast<int>(body.mesh.lines.rows());
  const auto quads = static_cast<int>(body.mesh.quads.rows());
  const Eigen::VectorXd values = stress.element_values(stress.row_at(t), lines + quads);
  vtkNew<vtkDoubleArray> cells;
  cells->SetName("stress");
  cells->SetNumberOfTuples(lines + quads + solids.cell_count());
  for (int q = 0; q < quads; ++q) cells->SetValue(q, values(lines + q));
  for (int e = 0; e < lines; ++e) cells->SetValue(quads + e, values(e));
  for (int c = 0; c < solids.cell_count(); ++c) {
    cells->SetValue(quads + lines + c, values(solids.beam[static_cast<std::size_t>(c)]));
  }
  grid->GetCellData()->AddArray(cells);
}

// The primitives of a rigid body at one sample, merged into one grid.
vtkSmartPointer<vtkUnstructuredGrid> rigid_grid(const BodyTrack& body, const BodyState& state) {
  vtkNew<vtkAppendFilter> append;
  append->MergePointsOff();
  for (const Shape& shape : body.shapes) {
    // The primitive's surface in its own frame (cylinders along z).
    vtkNew<vtkTransform> transform;
    transform->PostMultiply();
    const vtkSmartPointer<vtkPolyDataAlgorithm> source = primitive_source(shape, transform);
    // Shape offset, then body pose.
    const Eigen::Vector3d p = state.position + state.orientation * shape.offset_position;
    const Eigen::AngleAxisd rotation(state.orientation * shape.offset_orientation);
    transform->RotateWXYZ(rotation.angle() * 180.0 / M_PI, rotation.axis().data());
    transform->Translate(p.data());
    vtkNew<vtkTransformPolyDataFilter> placed;
    placed->SetInputConnection(source->GetOutputPort());
    placed->SetTransform(transform);
    placed->SetOutputPointsPrecision(vtkAlgorithm::DOUBLE_PRECISION);  // as the XDMF scene
    append->AddInputConnection(placed->GetOutputPort());
  }
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  if (!body.shapes.empty()) {
    append->Update();
    grid->ShallowCopy(append->GetOutput());
    grid->GetPointData()->Initialize();
  }
  add_vector_data(grid, RowMatrix3d::Zero(grid->GetNumberOfPoints(), 3));
  return grid;
}

// "<body>_<sample>.vtu", the body's name made safe and distinct (file_stem.h).
std::string file_name(const std::string& body, Eigen::Index sample) {
  char index[32];
  std::snprintf(index, sizeof index, "%05ld", static_cast<long>(sample));
  return file_stem(body) + "_" + index + ".vtu";
}

}  // namespace

int write_vtk_series(const Results& results, const std::filesystem::path& vtk_directory,
                     double t0, double t1) {
  std::filesystem::create_directories(vtk_directory);
  std::ofstream pvd(vtk_directory / results::kVtkSceneFileName);
  if (!pvd) throw std::runtime_error("cannot write '" + (vtk_directory / results::kVtkSceneFileName).string() + "'");
  pvd << "<?xml version=\"1.0\"?>\n"
      << "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
      << "  <Collection>\n";
  pvd << std::setprecision(17);

  // One file per body and sample in [t0, t1]; stresses where the run recorded them.
  const std::vector<std::optional<StressTrack>> stresses = read_stress_tracks(results);
  std::vector<BeamSolids> solids;
  for (const BodyTrack& body : results.bodies) solids.push_back(beam_solids(body.mesh));
  int written = 0;
  vtkNew<vtkXMLUnstructuredGridWriter> writer;
  writer->SetDataModeToAppended();
  writer->EncodeAppendedDataOff();
  for (Eigen::Index i = 0; i < results.sample_count(); ++i) {
    const double t = results.time(i);
    if (t < t0 || t > t1) continue;
    for (std::size_t b = 0; b < results.bodies.size(); ++b) {
      const BodyTrack& body = results.bodies[b];
      const BodyState state = body_state(body, {i, 0.0});
      const auto grid = body.flexible ? flexible_grid(body, state, solids[b]) : rigid_grid(body, state);
      if (body.flexible && stresses[b]) add_stress_data(grid, body, *stresses[b], t, solids[b]);
      const std::string name = file_name(body.name, i);
      writer->SetInputData(grid);
      writer->SetFileName((vtk_directory / name).c_str());
      if (writer->Write() != 1) {
        throw std::runtime_error("cannot write '" + (vtk_directory / name).string() + "'");
      }
      ++written;
      pvd << "    <DataSet timestep=\"" << t << "\" group=\"\" part=\"" << b << "\" name=\""
          << markup_escape(body.name) << "\" file=\"" << markup_escape(name) << "\"/>\n";
    }
  }
  pvd << "  </Collection>\n</VTKFile>\n";
  if (!pvd) throw std::runtime_error("cannot write '" + (vtk_directory / results::kVtkSceneFileName).string() + "'");
  return written;
}

}  // namespace limber::render
