#include "fe/assembly.h"

#include <fmt/format.h>

#include <algorithm>
#include <limits>
#include <utility>

#include "core/error.h"
#include "fe/beam_element.h"
#include "fe/shell_element.h"
#include "fe/shell_triangle.h"

namespace limber::fe {

namespace {

// Sorted neighbour lists of every node (itself included), compressed: the neighbours of
// node n are neighbours[start[n] .. start[n+1]).
struct NodeGraph {
  std::vector<int> start;
  std::vector<int> neighbours;
};

template <std::size_t N>
void add_clique(const std::array<int, N>& nodes, std::vector<std::pair<int, int>>& pairs) {
  for (int a : nodes) {
    for (int b : nodes) pairs.emplace_back(a, b);
  }
}

NodeGraph node_graph(const FeModel& model) {
  // Every (node, node) pair that shares an element, plus the diagonal.
  std::vector<std::pair<int, int>> pairs;
  pairs.reserve(model.node_count() + 4 * model.beams.size() + 16 * model.shells.size());
  for (int n = 0; n < model.node_count(); ++n) pairs.emplace_back(n, n);
  for (const BeamElement& beam : model.beams) add_clique(beam.nodes, pairs);
  for (const ShellElement& shell : model.shells) add_clique(shell.nodes, pairs);
  for (const ShellTriangle& triangle : model.triangles) add_clique(triangle.nodes, pairs);
  for (const auto* matrices : {&model.dof_stiffnesses, &model.dof_masses}) {
    for (const DofMatrix& matrix : *matrices) {
      for (int a : matrix.dofs) {
        for (int b : matrix.dofs) pairs.emplace_back(a / kDofsPerNode, b / kDofsPerNode);
      }
    }
  }
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());

  // Compress by first node.
  NodeGraph graph;
  graph.start.assign(model.node_count() + 1, 0);
  graph.neighbours.reserve(pairs.size());
  for (const auto& [n, m] : pairs) {
    ++graph.start[n + 1];
    graph.neighbours.push_back(m);
  }
  for (int n = 0; n < model.node_count(); ++n) graph.start[n + 1] += graph.start[n];
  return graph;
}

// Compressed column pattern with full 6x6 blocks: the 6 columns of node n each hold the
// rows of all 6 DOFs of every neighbour of n, in ascending order.
SparseMatrix block_pattern(const NodeGraph& graph, int node_count) {
  const int dofs = kDofsPerNode * node_count;
  const auto nonzeros = static_cast<Eigen::Index>(kDofsPerNode * kDofsPerNode) *
                        static_cast<Eigen::Index>(graph.neighbours.size());
  LIMBER_DEMAND(nonzeros < std::numeric_limits<int>::max());
  SparseMatrix pattern(dofs, dofs);
  pattern.resizeNonZeros(nonzeros);
  int* outer = pattern.outerIndexPtr();
  int* inner = pattern.innerIndexPtr();
  int entry = 0;
  for (int n = 0; n < node_count; ++n) {
    for (int b = 0; b < kDofsPerNode; ++b) {
      outer[kDofsPerNode * n + b] = entry;
      for (int k = graph.start[n]; k < graph.start[n + 1]; ++k) {
        for (int a = 0; a < kDofsPerNode; ++a)
          inner[entry++] = kDofsPerNode * graph.neighbours[k] + a;
      }
    }
  }
  outer[dofs] = entry;
  std::fill_n(pattern.valuePtr(), nonzeros, 0.0);
  return pattern;
}

// Adds element matrices in place into K and M sharing the block pattern.
class BlockAdder {
 public:
  BlockAdder(const NodeGraph& graph, StructuralMatrices& matrices)
      : graph_(graph), matrices_(matrices) {}

  // Adds the element matrices of nodes `nodes` (node-major 6 DOFs each).
  template <std::size_t N, typename Matrix>
  void add(const std::array<int, N>& nodes, const Matrix& stiffness, const Matrix& mass) {
    for (std::size_t j = 0; j < N; ++j) {
      for (std::size_t i = 0; i < N; ++i) {
        const int first = first_entry(nodes[i], nodes[j]);
        const int col_stride = column_length(nodes[j]);
        for (int b = 0; b < kDofsPerNode; ++b) {
          for (int a = 0; a < kDofsPerNode; ++a) {
            const int entry = first + b * col_stride + a;
            const auto row = static_cast<Eigen::Index>(kDofsPerNode * i + a);
            const auto col = static_cast<Eigen::Index>(kDofsPerNode * j + b);
            k_values()[entry] += stiffness(row, col);
            m_values()[entry] += mass(row, col);
          }
        }
      }
    }
  }

  // Adds a matrix on global DOFs to `values` (K's or M's, same pattern).
  void add_dof_matrix(const DofMatrix& matrix, double* values) {
    for (std::size_t j = 0; j < matrix.dofs.size(); ++j) {
      const int col_node = matrix.dofs[j] / kDofsPerNode, b = matrix.dofs[j] % kDofsPerNode;
      for (std::size_t i = 0; i < matrix.dofs.size(); ++i) {
        const int row_node = matrix.dofs[i] / kDofsPerNode, a = matrix.dofs[i] % kDofsPerNode;
        const int entry = first_entry(row_node, col_node) + b * column_length(col_node) + a;
        values[entry] += matrix.values(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j));
      }
    }
  }
  double* k_values() { return matrices_.stiffness.valuePtr(); }
  double* m_values() { return matrices_.mass.valuePtr(); }

  // Adds a 6x6 block to M only, on the diagonal of `node`.
  void add_mass_block(int node, const Eigen::Matrix<double, 6, 6>& block) {
    const int first = first_entry(node, node);
    const int col_stride = column_length(node);
    for (int b = 0; b < kDofsPerNode; ++b) {
      for (int a = 0; a < kDofsPerNode; ++a) m_values()[first + b * col_stride + a] += block(a, b);
    }
  }

 private:
  // Entry of (row DOF 0 of `row_node`, column DOF 0 of `col_node`).
  int first_entry(int row_node, int col_node) const {
    const auto begin = graph_.neighbours.begin() + graph_.start[col_node];
    const auto end = graph_.neighbours.begin() + graph_.start[col_node + 1];
    const auto found = std::lower_bound(begin, end, row_node);
    LIMBER_DEMAND(found != end && *found == row_node);
    const int position = static_cast<int>(found - begin);
    return matrices_.stiffness.outerIndexPtr()[kDofsPerNode * col_node] + kDofsPerNode * position;
  }
  int column_length(int node) const {
    return kDofsPerNode * (graph_.start[node + 1] - graph_.start[node]);
  }

  const NodeGraph& graph_;
  StructuralMatrices& matrices_;
};

}  // namespace

StructuralMatrices assemble(const FeModel& model) {
  // One pattern for K and M.
  const NodeGraph graph = node_graph(model);
  StructuralMatrices out;
  out.stiffness = block_pattern(graph, model.node_count());
  out.mass = out.stiffness;
  BlockAdder adder(graph, out);

  // Beams.
  for (const BeamElement& beam : model.beams) {
    const BeamElementMatrices e = beam_element_matrices(
        model.node_positions[beam.nodes[0]], model.node_positions[beam.nodes[1]], beam.orientation,
        model.beam_properties[beam.property]);
    adder.add(beam.nodes, e.stiffness, e.mass);
  }

  // Shells; a warp the flat element rejects is reported with the element's node ids.
  for (const ShellElement& shell : model.shells) {
    std::array<Eigen::Vector3d, 4> corners;
    for (int i = 0; i < 4; ++i) corners[i] = model.node_positions[shell.nodes[i]];
    try {
      const ShellElementMatrices e =
          shell_element_matrices(corners, model.shell_properties[shell.property]);
      adder.add(shell.nodes, e.stiffness, e.mass);
    } catch (const InputError& error) {
      throw InputError(fmt::format("shell {}-{}-{}-{}: {}", model.node_ids[shell.nodes[0]],
                                   model.node_ids[shell.nodes[1]], model.node_ids[shell.nodes[2]],
                                   model.node_ids[shell.nodes[3]], error.message()),
                       error.where());
    }
  }

  // Shell triangles, likewise.
  for (const ShellTriangle& triangle : model.triangles) {
    std::array<Eigen::Vector3d, 3> corners;
    for (int i = 0; i < 3; ++i) corners[i] = model.node_positions[triangle.nodes[i]];
    try {
      const ShellTriangleMatrices e =
          shell_triangle_matrices(corners, model.shell_properties[triangle.property]);
      adder.add(triangle.nodes, e.stiffness, e.mass);
    } catch (const InputError& error) {
      throw InputError(fmt::format("shell triangle {}-{}-{}: {}",
                                   model.node_ids[triangle.nodes[0]],
                                   model.node_ids[triangle.nodes[1]],
                                   model.node_ids[triangle.nodes[2]], error.message()),
                       error.where());
    }
  }

  // Point masses: m I3 on translations, the inertia tensor on rotations.
  for (const PointMass& point : model.point_masses) {
    Eigen::Matrix<double, 6, 6> block = Eigen::Matrix<double, 6, 6>::Zero();
    block.topLeftCorner<3, 3>().diagonal().setConstant(point.mass);
    block.bottomRightCorner<3, 3>() = point.inertia;
    adder.add_mass_block(point.node, block);
  }

  // Matrices on DOFs: springs, bushings and rods (K), general masses (M).
  for (const DofMatrix& matrix : model.dof_stiffnesses) adder.add_dof_matrix(matrix, adder.k_values());
  for (const DofMatrix& matrix : model.dof_masses) adder.add_dof_matrix(matrix, adder.m_values());
  return out;
}

std::vector<int> free_dofs(const FeModel& model) {
  std::vector<bool> fixed(model.dof_count(), false);
  for (const FixedDof& f : model.fixed_dofs) fixed[FeModel::dof_index(f.node, f.dof)] = true;
  std::vector<int> out;
  out.reserve(model.dof_count());
  for (int i = 0; i < model.dof_count(); ++i) {
    if (!fixed[i]) out.push_back(i);
  }
  return out;
}

SparseMatrix restrict_to(const SparseMatrix& matrix, const std::vector<int>& dofs) {
  LIMBER_DEMAND(matrix.rows() == matrix.cols());
  // New index of every old DOF (-1: dropped).
  std::vector<int> new_index(matrix.rows(), -1);
  for (std::size_t k = 0; k < dofs.size(); ++k) {
    LIMBER_DEMAND(dofs[k] >= 0 && dofs[k] < matrix.rows());
    LIMBER_DEMAND(new_index[dofs[k]] == -1);
    new_index[dofs[k]] = static_cast<int>(k);
  }

  // Columns in the order of `dofs`, kept rows renumbered and sorted within each column.
  const int n = static_cast<int>(dofs.size());
  std::vector<int> outer(n + 1, 0);
  std::vector<std::pair<int, double>> entries;
  entries.reserve(matrix.nonZeros());
  for (int j = 0; j < n; ++j) {
    const auto column_begin = entries.size();
    for (SparseMatrix::InnerIterator it(matrix, dofs[j]); it; ++it) {
      const int row = new_index[it.row()];
      if (row >= 0) entries.emplace_back(row, it.value());
    }
    std::sort(entries.begin() + static_cast<long>(column_begin), entries.end(),
              [](const auto& x, const auto& y) { return x.first < y.first; });
    outer[j + 1] = static_cast<int>(entries.size());
  }

  // Copy into a compressed matrix.
  SparseMatrix out(n, n);
  out.resizeNonZeros(static_cast<Eigen::Index>(entries.size()));
  std::copy(outer.begin(), outer.end(), out.outerIndexPtr());
  for (std::size_t k = 0; k < entries.size(); ++k) {
    out.innerIndexPtr()[k] = entries[k].first;
    out.valuePtr()[k] = entries[k].second;
  }
  return out;
}

}  // namespace limber::fe
