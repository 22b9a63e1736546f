#include "beam_solids.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "core/error.h"

namespace limber::render {

namespace {

// Twice the signed area of triangle (a, b, c): > 0 when counter-clockwise.
double turn(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c) {
  return (b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x());
}

// Whether q lies inside or on counter-clockwise triangle (a, b, c).
bool in_triangle(const Eigen::Vector2d& q, const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                 const Eigen::Vector2d& c) {
  return turn(a, b, q) >= 0.0 && turn(b, c, q) >= 0.0 && turn(c, a, q) >= 0.0;
}

}  // namespace

std::vector<std::array<int, 3>> triangulate_polygon(const std::vector<Eigen::Vector2d>& p) {
  std::vector<std::array<int, 3>> triangles;
  std::vector<int> left(p.size());
  std::iota(left.begin(), left.end(), 0);
  while (left.size() > 3) {
    const std::size_t m = left.size();
    bool clipped = false;
    // An ear: a convex corner whose triangle holds no other remaining corner.
    for (std::size_t k = 0; k < m && !clipped; ++k) {
      const int a = left[(k + m - 1) % m], b = left[k], c = left[(k + 1) % m];
      if (!(turn(p[a], p[b], p[c]) > 0.0)) continue;
      const bool empty = std::none_of(left.begin(), left.end(), [&](int q) {
        return q != a && q != b && q != c && in_triangle(p[q], p[a], p[b], p[c]);
      });
      if (!empty) continue;
      triangles.push_back({a, b, c});
      left.erase(left.begin() + static_cast<std::ptrdiff_t>(k));
      clipped = true;
    }
    // No ear: only straight (collinear) corners are left to cut; drop the flattest.
    if (!clipped) {
      std::size_t flattest = 0;
      double least = INFINITY;
      for (std::size_t k = 0; k < m; ++k) {
        const double t = std::abs(turn(p[left[(k + m - 1) % m]], p[left[k]], p[left[(k + 1) % m]]));
        if (t < least) least = t, flattest = k;
      }
      left.erase(left.begin() + static_cast<std::ptrdiff_t>(flattest));
    }
  }
  if (left.size() == 3 && turn(p[left[0]], p[left[1]], p[left[2]]) > 0.0) {
    triangles.push_back({left[0], left[1], left[2]});
  }
  return triangles;
}

BeamSolids beam_solids(const FlexibleMesh& mesh) {
  BeamSolids out;
  const results::BeamSections& s = mesh.beam_sections;
  if (s.empty()) return out;
  LIMBER_DEMAND(static_cast<Eigen::Index>(s.outline.size()) == mesh.lines.rows());

  // Each outline's polygons and, for a solid one, its cap triangles, once.
  const int no = s.outline_count();
  std::vector<std::vector<Eigen::Vector2d>> outlines(static_cast<std::size_t>(no));
  std::vector<std::vector<std::array<int, 3>>> caps(static_cast<std::size_t>(no));
  std::size_t total = 0;
  for (int k = 0; k < no; ++k) {
    for (int i = s.offsets[k]; i < s.offsets[k + 1]; ++i) outlines[k].push_back(s.points.row(i).transpose());
    if (!s.hollow[k]) caps[k] = triangulate_polygon(outlines[k]);
  }
  for (int o : s.outline) total += 2 * outlines[static_cast<std::size_t>(o)].size();
  out.points_B.resize(static_cast<Eigen::Index>(total), 3);
  out.node.reserve(total);

  const auto add_cell = [&](std::initializer_list<int> ids, int e) {
    out.connectivity.insert(out.connectivity.end(), ids);
    out.cell_offsets.push_back(static_cast<int>(out.connectivity.size()));
    out.beam.push_back(e);
  };
  Eigen::Index next = 0;
  for (Eigen::Index e = 0; e < mesh.lines.rows(); ++e) {
    const int beam = static_cast<int>(e);
    const auto& outline = outlines[static_cast<std::size_t>(s.outline[static_cast<std::size_t>(e)])];
    const auto& cap = caps[static_cast<std::size_t>(s.outline[static_cast<std::size_t>(e)])];
    const bool hollow = s.hollow[static_cast<std::size_t>(s.outline[static_cast<std::size_t>(e)])] != 0;
    const int n = static_cast<int>(outline.size());

    // Local axes of the beam in the body frame.
    const int node_a = mesh.lines(e, 0), node_b = mesh.lines(e, 1);
    const Eigen::Vector3d X_a = mesh.nodes.row(node_a).transpose();
    const Eigen::Vector3d X_b = mesh.nodes.row(node_b).transpose();
    LIMBER_DEMAND((X_b - X_a).norm() > 0.0);
    const Eigen::Vector3d x = (X_b - X_a).normalized();
    const Eigen::Vector3d y = s.y_axes.row(e).transpose();
    LIMBER_DEMAND(std::abs(x.dot(y)) < 1e-6);
    const Eigen::Vector3d z = x.cross(y);

    // Two rings of outline points: ring r's point i is base + r n + i.
    const int base = static_cast<int>(next);
    for (int r = 0; r < 2; ++r) {
      const Eigen::Vector3d& X_end = r == 0 ? X_a : X_b;
      for (const Eigen::Vector2d& q : outline) {
        out.points_B.row(next++) = (X_end + q.x() * y + q.y() * z).transpose();
        out.node.push_back(r == 0 ? node_a : node_b);
      }
    }
    const auto ring = [&](int r, int i) { return base + r * n + i; };

    // Sides: a quad per polygon edge, the inner polygon's turned to face the hole.
    const int polygon_size = hollow ? n / 2 : n;
    for (int first = 0; first < n; first += polygon_size) {
      const bool inner = first > 0;
      for (int k = 0; k < polygon_size; ++k) {
        const int i = first + k, j = first + (k + 1) % polygon_size;
        if (inner) add_cell({ring(0, j), ring(0, i), ring(1, i), ring(1, j)}, beam);
        else add_cell({ring(0, i), ring(0, j), ring(1, j), ring(1, i)}, beam);
      }
    }
    // Caps: ring 1 faces +x (the outline's own turning), ring 0 faces −x (reversed).
    if (hollow) {
      const int m = n / 2;
      for (int k = 0; k < m; ++k) {
        const int i = k, j = (k + 1) % m;
        add_cell({ring(1, i), ring(1, j), ring(1, m + j), ring(1, m + i)}, beam);
        add_cell({ring(0, i), ring(0, m + i), ring(0, m + j), ring(0, j)}, beam);
      }
    } else {
      for (const auto& t : cap) {
        add_cell({ring(1, t[0]), ring(1, t[1]), ring(1, t[2])}, beam);
        add_cell({ring(0, t[0]), ring(0, t[2]), ring(0, t[1])}, beam);
      }
    }
  }
  return out;
}

}  // namespace limber::render
