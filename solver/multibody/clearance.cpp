#include "multibody/clearance.h"
#include "multibody/clearance_minimum.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <utility>

#include "core/error.h"
#include "multibody/body.h"
#include "multibody/rotation.h"

namespace limber::multibody {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
// Candidates whose lower bound is within this relative margin of the best are skipped:
// parallel surfaces tie exactly and would otherwise be scanned in full; the answer moves by
// at most this fraction of itself.
constexpr double kTieMargin = 1e-12;

// Axis-aligned bounding box in ground axes.
struct Aabb {
  Eigen::Vector3d lower = Eigen::Vector3d::Constant(kInfinity);
  Eigen::Vector3d upper = Eigen::Vector3d::Constant(-kInfinity);

  void add(const Eigen::Vector3d& p) {
    lower = lower.cwiseMin(p);
    upper = upper.cwiseMax(p);
  }
  // Squared distance from p to the box (0 inside).
  double squared_gap(const Eigen::Vector3d& p) const {
    const Eigen::Vector3d d = (lower - p).cwiseMax(p - upper).cwiseMax(0.0);
    return d.squaredNorm();
  }
};

// A box placed in ground: centre, axes (columns of R_WS) and half edges [m].
struct OrientedBox {
  Eigen::Vector3d center_W = Eigen::Vector3d::Zero();
  Eigen::Matrix3d R_WS = Eigen::Matrix3d::Identity();
  Eigen::Vector3d half = Eigen::Vector3d::Zero();
};

// A body's surfaces at one state: vertices (mesh nodes first, then box corners), the mesh's
// triangles over the first `mesh_vertices` of them with their bounding boxes, and the boxes.
struct Surface {
  int body = 0;
  std::vector<Eigen::Vector3d> vertices;
  int mesh_vertices = 0;
  std::vector<std::array<int, 3>> triangles;
  std::vector<Aabb> triangle_boxes;
  Aabb mesh_box;
  std::vector<OrientedBox> boxes;
};

// Closest point found so far for one pair; a is the vertex's surface when not swapped.
struct Best {
  double distance = kInfinity;
  Eigen::Vector3d point_a_W = Eigen::Vector3d::Zero(), point_b_W = Eigen::Vector3d::Zero();

  void offer(double d, const Eigen::Vector3d& on_vertex, const Eigen::Vector3d& on_target,
             bool swapped) {
    if (d >= distance) return;
    distance = d;
    point_a_W = swapped ? on_target : on_vertex;
    point_b_W = swapped ? on_vertex : on_target;
  }
};

bool has_quads(const Body& body) {
  return body.kind == BodyKind::kFlexible && !body.flexible->mesh.quads.empty();
}

// Edge lengths of the box that holds a shape (docs of Shape::size).
Eigen::Vector3d bounding_edges(const Shape& shape) {
  switch (shape.type) {
    case ShapeType::kBox: return shape.size;
    case ShapeType::kCylinder: return Eigen::Vector3d(2 * shape.size(0), 2 * shape.size(1), shape.size(2));
    case ShapeType::kSphere: return 2.0 * shape.size;
  }
  LIMBER_DEMAND(false);
}

Surface build_surface(const Model& model, int body_index, const Eigen::VectorXd& q) {
  const Body& body = model.bodies[body_index];
  Surface surface;
  surface.body = body_index;
  // Pose of the body (floating) frame.
  Eigen::Vector3d r_WB = Eigen::Vector3d::Zero();
  Eigen::Matrix3d R_WB = Eigen::Matrix3d::Identity();
  if (body.kind != BodyKind::kGround) {
    r_WB = q.segment<3>(body.q_offset);
    R_WB = rotation_matrix(q.segment<4>(body.q_offset + 3));
  }

  // Shell mid-surface: deformed nodes p = r + A (x + Φ_t η) of the quads' nodes only.
  if (has_quads(body)) {
    const FlexibleBody& flexible = *body.flexible;
    const Eigen::VectorXd u = flexible.shapes * q.segment(body.q_offset + 7, flexible.mode_count());
    std::vector<int> vertex_of_node(static_cast<std::size_t>(flexible.node_count()), -1);
    const auto vertex = [&](int node) {
      int& v = vertex_of_node[static_cast<std::size_t>(node)];
      if (v < 0) {
        v = static_cast<int>(surface.vertices.size());
        const Eigen::Vector3d s_B = flexible.node_positions.col(node) + u.segment<3>(6 * node);
        surface.vertices.push_back(r_WB + R_WB * s_B);
        surface.mesh_box.add(surface.vertices.back());
      }
      return v;
    };
    for (const std::array<int, 4>& quad : flexible.mesh.quads) {
      const int a = vertex(quad[0]), b = vertex(quad[1]), c = vertex(quad[2]), d = vertex(quad[3]);
      surface.triangles.push_back({a, b, c});
      surface.triangles.push_back({a, c, d});
    }
    surface.mesh_vertices = static_cast<int>(surface.vertices.size());
    for (const std::array<int, 3>& t : surface.triangles) {
      Aabb box;
      for (int k : t) box.add(surface.vertices[static_cast<std::size_t>(k)]);
      surface.triangle_boxes.push_back(box);
    }
  }

  // Boxes (cylinders and spheres by their bounding box) and their corners as vertices.
  for (const Shape& shape : body.shapes) {
    OrientedBox box;
    box.R_WS = R_WB * rotation_matrix(shape.offset.orientation);
    box.center_W = r_WB + R_WB * shape.offset.position;
    box.half = 0.5 * bounding_edges(shape);
    for (int corner = 0; corner < 8; ++corner) {
      const Eigen::Vector3d sign((corner & 1) ? 1.0 : -1.0, (corner & 2) ? 1.0 : -1.0,
                                 (corner & 4) ? 1.0 : -1.0);
      surface.vertices.push_back(box.center_W + box.R_WS * sign.cwiseProduct(box.half));
    }
    surface.boxes.push_back(box);
  }
  return surface;
}

// Signed distance from p to the box (negative inside: minus the depth below the nearest
// face) and the closest point of its surface.
double box_distance(const OrientedBox& box, const Eigen::Vector3d& p_W, Eigen::Vector3d& closest_W) {
  const Eigen::Vector3d d = box.R_WS.transpose() * (p_W - box.center_W);
  const Eigen::Vector3d excess = d.cwiseAbs() - box.half;
  Eigen::Vector3d on_surface = d.cwiseMax(-box.half).cwiseMin(box.half);
  double distance = 0.0;
  Eigen::Index face = 0;
  const double deepest = excess.maxCoeff(&face);
  if (deepest > 0.0) {
    // Outside: the clamped point.
    distance = (d - on_surface).norm();
  } else {
    // Inside (or on the surface): pushed out through the nearest face.
    on_surface(face) = d(face) < 0.0 ? -box.half(face) : box.half(face);
    distance = deepest;
  }
  closest_W = box.center_W + box.R_WS * on_surface;
  return distance;
}

// Closest point of triangle abc to p (Ericson 2005, §5.1.5: Voronoi regions of the
// vertices, edges and face).
Eigen::Vector3d closest_on_triangle(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                                    const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  const Eigen::Vector3d ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0.0 && d2 <= 0.0) return a;
  const Eigen::Vector3d bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0.0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) return a + d1 / (d1 - d3) * ab;
  const Eigen::Vector3d cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0.0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) return a + d2 / (d2 - d6) * ac;
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && d4 - d3 >= 0.0 && d5 - d6 >= 0.0) {
    return b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b);
  }
  const double denominator = 1.0 / (va + vb + vc);
  return a + ab * (vb * denominator) + ac * (vc * denominator);
}

// Vertices of `from` (indices in `active`) against the boxes of `to`.
void vertices_to_boxes(const Surface& from, const std::vector<int>& active, const Surface& to,
                       bool swapped, Best& best) {
  Eigen::Vector3d closest;
  for (const OrientedBox& box : to.boxes) {
    for (int v : active) {
      const Eigen::Vector3d& p = from.vertices[static_cast<std::size_t>(v)];
      best.offer(box_distance(box, p, closest), p, closest, swapped);
    }
  }
}

// Vertices of `from` against the triangles of `to`, nearest to its bounding box first,
// stopping when the box is farther than the best distance (unsigned: no gain once ≤ 0).
void vertices_to_triangles(const Surface& from, const std::vector<int>& active, const Surface& to,
                           bool swapped, Best& best) {
  if (to.triangles.empty() || best.distance <= 0.0) return;
  const auto cut2 = [&] { return (1.0 - 2.0 * kTieMargin) * best.distance * best.distance; };
  // Only vertices nearer the bounding box than the best can gain (often none: the pair's
  // early-out), nearest first.
  std::vector<std::pair<double, int>> order;
  for (int v : active) {
    const double gap2 = to.mesh_box.squared_gap(from.vertices[static_cast<std::size_t>(v)]);
    if (gap2 < cut2()) order.emplace_back(gap2, v);
  }
  std::sort(order.begin(), order.end());
  for (const auto& [gap2, v] : order) {
    if (gap2 >= cut2()) break;
    const Eigen::Vector3d& p = from.vertices[static_cast<std::size_t>(v)];
    for (std::size_t t = 0; t < to.triangles.size(); ++t) {
      // Skip triangles whose bounding box is already (about) as far as the best.
      if (to.triangle_boxes[t].squared_gap(p) >= cut2()) continue;
      const std::array<int, 3>& tri = to.triangles[t];
      const Eigen::Vector3d closest =
          closest_on_triangle(p, to.vertices[static_cast<std::size_t>(tri[0])],
                              to.vertices[static_cast<std::size_t>(tri[1])],
                              to.vertices[static_cast<std::size_t>(tri[2])]);
      best.offer((p - closest).norm(), p, closest, swapped);
    }
  }
}

// Indices of the vertices of `surface` at least `band` from every point of `joints`.
std::vector<int> active_vertices(const Surface& surface, const std::vector<Eigen::Vector3d>& joints,
                                 double band) {
  std::vector<int> active;
  active.reserve(surface.vertices.size());
  for (std::size_t v = 0; v < surface.vertices.size(); ++v) {
    const bool in_band = std::any_of(joints.begin(), joints.end(), [&](const Eigen::Vector3d& p) {
      return (surface.vertices[v] - p).squaredNorm() < band * band;
    });
    if (!in_band) active.push_back(static_cast<int>(v));
  }
  return active;
}

// Origins of the markers of every joint between bodies a and b, in ground.
std::vector<Eigen::Vector3d> joint_points(const Model& model, int a, int b, const Eigen::VectorXd& q) {
  std::vector<Eigen::Vector3d> points;
  FrameKinematics frame;
  for (const Joint& joint : model.joints) {
    const int i = model.markers[joint.marker_i].body, j = model.markers[joint.marker_j].body;
    if (!((i == a && j == b) || (i == b && j == a))) continue;
    for (int marker : {joint.marker_i, joint.marker_j}) {
      marker_kinematics(model, marker, q, nullptr, frame);
      points.push_back(frame.p_W);
    }
  }
  return points;
}

}  // namespace

std::vector<int> bodies_with_surfaces(const Model& model) {
  std::vector<int> bodies;
  for (std::size_t b = 0; b < model.bodies.size(); ++b) {
    const Body& body = model.bodies[b];
    if (has_quads(body) || !body.shapes.empty()) bodies.push_back(static_cast<int>(b));
  }
  return bodies;
}

std::vector<ClearancePair> clearance_pairs(const Model& model) {
  const std::vector<int> bodies = bodies_with_surfaces(model);
  std::vector<ClearancePair> pairs;
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    for (std::size_t j = i + 1; j < bodies.size(); ++j) pairs.push_back({bodies[i], bodies[j]});
  }
  return pairs;
}

std::string pair_name(const Model& model, const ClearancePair& pair) {
  return model.bodies[static_cast<std::size_t>(pair.body_a)].name + ", " +
         model.bodies[static_cast<std::size_t>(pair.body_b)].name;
}

namespace {

// Every body's surface at this state, once; indexed by body (−1: none).
struct Surfaces {
  std::vector<Surface> list;
  std::vector<int> of_body;
};

Surfaces build_surfaces(const Model& model, const Eigen::VectorXd& q) {
  Surfaces out;
  out.of_body.assign(model.bodies.size(), -1);
  for (int b : bodies_with_surfaces(model)) {
    out.of_body[static_cast<std::size_t>(b)] = static_cast<int>(out.list.size());
    out.list.push_back(build_surface(model, b, q));
  }
  return out;
}

// One pair's clearance: vertices of either surface against the other's boxes and triangles.
Best pair_clearance(const Model& model, const Surfaces& surfaces, const ClearancePair& pair,
                    const Eigen::VectorXd& q, const ClearanceOptions& options) {
  const Surface& a = surfaces.list[static_cast<std::size_t>(surfaces.of_body[static_cast<std::size_t>(pair.body_a)])];
  const Surface& b = surfaces.list[static_cast<std::size_t>(surfaces.of_body[static_cast<std::size_t>(pair.body_b)])];
  // Vertices near a joint between the two touch by design.
  const std::vector<Eigen::Vector3d> joints = joint_points(model, pair.body_a, pair.body_b, q);
  const std::vector<int> active_a = active_vertices(a, joints, options.joint_band);
  const std::vector<int> active_b = active_vertices(b, joints, options.joint_band);
  // Boxes first (signed, cheap), then triangles with the best distance as a cut.
  Best best;
  vertices_to_boxes(a, active_a, b, false, best);
  vertices_to_boxes(b, active_b, a, true, best);
  vertices_to_triangles(a, active_a, b, false, best);
  vertices_to_triangles(b, active_b, a, true, best);
  return best;
}

// Everything of a surface (its vertices, hence its triangles and its boxes' corners) lies in
// this box.
Aabb surface_box(const Surface& surface) {
  Aabb box;
  for (const Eigen::Vector3d& p : surface.vertices) box.add(p);
  return box;
}

// A lower bound of every distance pair_clearance can find between two surfaces in these
// boxes: the gap between the boxes, less a margin for the rounding of the distances (1e-9 of
// the boxes' coordinates, a nanometre at a metre); −∞ when they overlap (a vertex inside a
// box of the other has a negative distance).
double lower_bound(const Aabb& a, const Aabb& b) {
  const Eigen::Vector3d gap = (a.lower - b.upper).cwiseMax(b.lower - a.upper).cwiseMax(0.0);
  if (gap.maxCoeff() <= 0.0) return -kInfinity;
  const double scale = a.lower.cwiseAbs().cwiseMax(a.upper.cwiseAbs()).cwiseMax(b.lower.cwiseAbs()).cwiseMax(b.upper.cwiseAbs()).maxCoeff();
  return gap.norm() - 1e-9 * (1.0 + scale);
}

}  // namespace

Clearance compute_clearance(const Model& model, const State& state, const ClearanceOptions& options) {
  LIMBER_DEMAND(state.q.size() == model.nq);
  LIMBER_DEMAND(options.joint_band >= 0.0);
  const Surfaces surfaces = build_surfaces(model, state.q);
  Clearance result;
  for (const ClearancePair& pair : clearance_pairs(model)) {
    const Best best = pair_clearance(model, surfaces, pair, state.q, options);
    result.pairs.push_back({pair, best.distance, best.point_a_W, best.point_b_W});
    if (best.distance < result.minimum) {
      result.minimum = best.distance;
      result.minimum_pair = static_cast<int>(result.pairs.size()) - 1;
    }
  }
  return result;
}

ClearanceMinimum minimum_clearance(const Model& model, const State& state, const ClearanceOptions& options) {
  LIMBER_DEMAND(state.q.size() == model.nq);
  LIMBER_DEMAND(options.joint_band >= 0.0);
  const Surfaces surfaces = build_surfaces(model, state.q);
  std::vector<Aabb> boxes;
  for (const Surface& surface : surfaces.list) boxes.push_back(surface_box(surface));
  // Pairs by their lower bound, nearest first, so that the far ones are skipped.
  const std::vector<ClearancePair> pairs = clearance_pairs(model);
  std::vector<std::pair<double, int>> order;
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    const Aabb& a = boxes[static_cast<std::size_t>(surfaces.of_body[static_cast<std::size_t>(pairs[k].body_a)])];
    const Aabb& b = boxes[static_cast<std::size_t>(surfaces.of_body[static_cast<std::size_t>(pairs[k].body_b)])];
    order.emplace_back(lower_bound(a, b), static_cast<int>(k));
  }
  std::sort(order.begin(), order.end());
  ClearanceMinimum result;
  for (const auto& [bound, k] : order) {
    // No distance of this pair can reach the smallest so far (nor tie it: the bound is
    // strictly above), nor can any later pair's.
    if (bound > result.minimum) break;
    const double distance = pair_clearance(model, surfaces, pairs[static_cast<std::size_t>(k)], state.q, options).distance;
    // Ties go to the first pair in clearance_pairs' order, as in compute_clearance.
    if (distance < result.minimum || (distance == result.minimum && result.pair >= 0 && k < result.pair)) {
      result.minimum = distance;
      result.pair = k;
    }
  }
  return result;
}

}  // namespace limber::multibody
