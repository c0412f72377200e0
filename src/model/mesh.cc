// Mesh generation for every `mesh.kind`: node positions, the spring topology by family, surface
// triangles and the lumped area (or length) of each node.
//
// Conventions (also in docs/reference.md's scene reference):
// - grid: node (i, j) has id j*nu + i. A single row (nodes [n, 1]) or column is a strip whose
//   width is the other entry of `size`; its nodes carry length × width as area.
// - chain: a single row of nodes (nu = n, nv = 1, grid_index (k, 0)), so that edge/corner/ij
//   selectors address its ends; its lumped length is half of each adjacent segment. Its nodes are
//   evenly spaced along `direction`, or the explicit `points` (offset by `origin`); a closed chain
//   also links the last node to the first, and `loop` lists its links in order.
// - circle: lattice points (i s, j s) of spacing s, with the origin a lattice point, inside the
//   disc; full lattice cells give 2 triangles, cells with 3 corners inside the disc one. The
//   lumped areas are the disc cut into the lattice's cells (boundary control volumes take the
//   part of the disc beyond the lattice's staircase outline): they add up to πR², so the
//   specimen's mass is πR²ρ at every spacing. The triangles cover the staircase polygon; the
//   fringe (struct Fringe) covers the rest of the disc for the drape coefficient's shadow.
// - arc: node 0 is the centre, then ring r = 1..rings, spoke k: id 1 + (r-1)*spokes + k.
// - file: OBJ, PLY (ASCII or binary) or STL (ASCII or binary), read by src/scene/mesh_file.h;
//   node ids are the vertex order, from 0 (OBJ counts from 1; STL: in order of first appearance,
//   exactly equal vertices merged).
#include "src/model/mesh.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <map>
#include <set>
#include <string>
#include <unordered_map>

#include "src/scene/mesh_file.h"

namespace drape {

namespace {

Link Ordered(int a, int b) { return a < b ? Link{a, b} : Link{b, a}; }

// Area of triangle abc.
double TriangleArea(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  return 0.5 * (b - a).cross(c - a).norm();
}

// Adds a third of each triangle's area to each of its vertices.
void LumpTriangleAreas(Mesh* mesh) {
  mesh->area.assign(mesh->nodes.size(), 0.0);
  for (const auto& t : mesh->triangles) {
    const double third =
        TriangleArea(mesh->nodes[t[0]], mesh->nodes[t[1]], mesh->nodes[t[2]]) / 3.0;
    for (int v : t) mesh->area[v] += third;
  }
}

// The nodes as the columns of a 3 × n matrix (Eigen::Vector3d is three packed doubles).
Eigen::Map<const Eigen::Matrix3Xd> AsColumns(const std::vector<Eigen::Vector3d>& nodes) {
  static_assert(sizeof(Eigen::Vector3d) == 3 * sizeof(double), "Vector3d is not packed");
  return {nodes.empty() ? nullptr : nodes[0].data(), 3, static_cast<Eigen::Index>(nodes.size())};
}

// ---------------------------------------------------------------------------------------------
// grid

// Coordinates along one grid axis: the explicit list, or `count` points evenly over `extent`.
std::vector<double> AxisCoordinates(const std::vector<double>& explicit_values, int count,
                                    double extent, const char* axis, const Location& where) {
  if (!explicit_values.empty()) {
    for (size_t k = 1; k < explicit_values.size(); ++k) {
      if (!(explicit_values[k] > explicit_values[k - 1])) {
        throw InputError(where, std::string("grid coordinates ") + axis +
                                    " must be strictly increasing (entries " +
                                    std::to_string(k - 1) + " and " + std::to_string(k) + ")");
      }
    }
    return explicit_values;
  }
  if (count < 1) {
    throw InputError(where, std::string("a grid needs at least 1 node along ") + axis);
  }
  std::vector<double> values(count, 0.0);
  for (int k = 1; k < count; ++k) values[k] = extent * k / (count - 1);
  return values;
}

// Half of each adjacent interval: the lumped length of each point of a line.
std::vector<double> LumpedLengths(const std::vector<double>& coordinates) {
  std::vector<double> lengths(coordinates.size(), 0.0);
  for (size_t k = 0; k + 1 < coordinates.size(); ++k) {
    const double half = 0.5 * (coordinates[k + 1] - coordinates[k]);
    lengths[k] += half;
    lengths[k + 1] += half;
  }
  return lengths;
}

void AddGridLinks(int nu, int nv, Mesh* mesh) {
  auto id = [nu](int i, int j) { return j * nu + i; };
  for (int j = 0; j < nv; ++j) {
    for (int i = 0; i < nu; ++i) {
      if (i + 1 < nu) mesh->warp.push_back({id(i, j), id(i + 1, j)});
      if (j + 1 < nv) mesh->weft.push_back({id(i, j), id(i, j + 1)});
      if (i + 1 < nu && j + 1 < nv) {
        mesh->shear.push_back({id(i, j), id(i + 1, j + 1)});
        mesh->shear.push_back({id(i + 1, j), id(i, j + 1)});
        mesh->triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
        mesh->triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
      }
      if (i + 2 < nu) mesh->flexion_warp.push_back({id(i, j), id(i + 2, j)});
      if (j + 2 < nv) mesh->flexion_weft.push_back({id(i, j), id(i, j + 2)});
    }
  }
}

// Lumped areas: each cell's area a quarter to each corner; a single row or column is a strip of
// width `strip_width`, each node carrying its lumped length times that width.
void AddGridAreas(const std::vector<double>& u, const std::vector<double>& v,
                  const Eigen::Vector2d& strip_width, Mesh* mesh) {
  const int nu = static_cast<int>(u.size()), nv = static_cast<int>(v.size());
  mesh->area.assign(nu * nv, 0.0);
  if (nu == 1 || nv == 1) {
    const bool row = nv == 1;
    mesh->length = LumpedLengths(row ? u : v);
    const double width = row ? strip_width.y() : strip_width.x();
    for (int k = 0; k < nu * nv; ++k) mesh->area[k] = mesh->length[k] * width;
    return;
  }
  for (int j = 0; j + 1 < nv; ++j) {
    for (int i = 0; i + 1 < nu; ++i) {
      const double quarter = 0.25 * (u[i + 1] - u[i]) * (v[j + 1] - v[j]);
      for (int dj = 0; dj < 2; ++dj) {
        for (int di = 0; di < 2; ++di) mesh->area[(j + dj) * nu + i + di] += quarter;
      }
    }
  }
}

Mesh BuildGrid(const MeshSpec& spec) {
  if (spec.plane != "xy" && spec.plane != "xz") {
    throw InputError(spec.where, "unknown grid plane '" + spec.plane + "' (use xy or xz)");
  }
  const std::vector<double> u =
      AxisCoordinates(spec.u, spec.nodes[0], spec.size.x(), "u", spec.where);
  const std::vector<double> v =
      AxisCoordinates(spec.v, spec.nodes[1], spec.size.y(), "v", spec.where);
  Mesh mesh;
  mesh.nu = static_cast<int>(u.size());
  mesh.nv = static_cast<int>(v.size());
  for (int j = 0; j < mesh.nv; ++j) {
    for (int i = 0; i < mesh.nu; ++i) {
      const Eigen::Vector3d offset =
          spec.plane == "xy" ? Eigen::Vector3d(u[i], v[j], 0.0) : Eigen::Vector3d(u[i], 0.0, v[j]);
      mesh.nodes.push_back(spec.origin + offset);
      mesh.grid_index.push_back({i, j});
    }
  }
  AddGridLinks(mesh.nu, mesh.nv, &mesh);
  AddGridAreas(u, v, spec.size, &mesh);
  if (mesh.nv == 1) mesh.lines = mesh.warp;  // a single row has no faces: draw it as a line
  if (mesh.nu == 1) mesh.lines = mesh.weft;
  return mesh;
}

// ---------------------------------------------------------------------------------------------
// chain

// Chain nodes: the explicit points, or `chain_nodes` evenly along `direction` over `length`.
std::vector<Eigen::Vector3d> ChainPoints(const MeshSpec& spec) {
  if (!spec.points.empty()) {
    std::vector<Eigen::Vector3d> points;
    for (const auto& p : spec.points) points.push_back(spec.origin + p);
    return points;
  }
  const double norm = spec.direction.norm();
  if (!(norm > 0.0)) throw InputError(spec.where, "chain direction must not be zero");
  if (spec.chain_nodes < 2) throw InputError(spec.where, "a chain needs at least 2 nodes");
  const Eigen::Vector3d step = spec.direction / norm * (spec.length / (spec.chain_nodes - 1));
  std::vector<Eigen::Vector3d> points;
  points.reserve(spec.chain_nodes);
  for (int k = 0; k < spec.chain_nodes; ++k) points.push_back(spec.origin + k * step);
  return points;
}

// A chain: warp links between consecutive nodes, flexion links between every other node; a closed
// chain also links its last node back to its first (and wraps the flexion links).
Mesh BuildChain(const MeshSpec& spec) {
  Mesh mesh;
  mesh.nodes = ChainPoints(spec);
  const int n = static_cast<int>(mesh.nodes.size());
  if (n < 2) throw InputError(spec.where, "a chain needs at least 2 nodes");
  if (spec.closed && n < 3) throw InputError(spec.where, "a closed chain needs at least 3 nodes");
  mesh.nu = n;
  mesh.nv = 1;
  const int links = spec.closed ? n : n - 1;
  const int flexion = spec.closed ? (n > 4 ? n : 0) : n - 2;  // no pair twice
  for (int k = 0; k < n; ++k) mesh.grid_index.push_back({k, 0});
  for (int k = 0; k < links; ++k) mesh.warp.push_back({k, (k + 1) % n});
  for (int k = 0; k < flexion; ++k) mesh.flexion_warp.push_back({k, (k + 2) % n});
  mesh.lines = mesh.warp;
  if (spec.closed) mesh.loop = mesh.warp;
  mesh.length.assign(n, 0.0);
  for (const Link& link : mesh.warp) {
    const double half = 0.5 * (mesh.nodes[link[1]] - mesh.nodes[link[0]]).norm();
    mesh.length[link[0]] += half;
    mesh.length[link[1]] += half;
  }
  mesh.area.assign(n, 0.0);
  return mesh;
}

// ---------------------------------------------------------------------------------------------
// circle

// Area of the disc x² + y² ≤ r² inside the rectangle [x0, x1] × [y0, y1]: the integral over x of
// the chord length within [y0, y1], by composite Simpson's rule on pieces split where the
// integrand has a kink (x = ±r, and where the circle crosses y = y0 or y = y1). Over a whole
// circle mesh the error is ~1e-7 of the disc's area (the square-root ends at x = ±r).
double DiscAreaInRectangle(double r, double x0, double x1, double y0, double y1) {
  auto chord = [&](double x) {
    const double s = x * x < r * r ? std::sqrt(r * r - x * x) : 0.0;
    return std::max(0.0, std::min(y1, s) - std::max(y0, -s));
  };
  std::vector<double> cuts{x0, x1};
  for (double y : {y0, y1}) {
    if (std::abs(y) < r) {
      const double x = std::sqrt(r * r - y * y);
      cuts.push_back(x), cuts.push_back(-x);
    }
  }
  cuts.push_back(r), cuts.push_back(-r);
  std::sort(cuts.begin(), cuts.end());
  double area = 0.0;
  constexpr int kIntervals = 64;  // per piece, even
  for (size_t k = 0; k + 1 < cuts.size(); ++k) {
    const double a = std::max(cuts[k], x0), b = std::min(cuts[k + 1], x1);
    if (!(b > a)) continue;
    const double step = (b - a) / kIntervals;
    double sum = chord(a) + chord(b);
    for (int n = 1; n < kIntervals; ++n) sum += (n % 2 ? 4.0 : 2.0) * chord(a + n * step);
    area += sum * step / 3.0;
  }
  return area;
}

// Triangles of one lattice cell with corners a (i, j), b (i+1, j), c (i+1, j+1), d (i, j+1), ids
// -1 where outside the disc: 2 for a full cell, 1 for a cell with 3 corners inside.
void AddCircleCellTriangles(int a, int b, int c, int d, Mesh* mesh) {
  const int present = (a >= 0) + (b >= 0) + (c >= 0) + (d >= 0);
  if (present == 4) {
    mesh->triangles.push_back({a, b, c});
    mesh->triangles.push_back({a, c, d});
  } else if (present == 3) {
    std::array<int, 3> triangle{};
    int k = 0;
    for (int v : {a, b, c, d}) {
      if (v >= 0) triangle[k++] = v;
    }
    mesh->triangles.push_back(triangle);
  }
}

// Lumped areas of one lattice cell [x0, x0 + s] × [y0, y0 + s] (disc-centred coordinates) with
// corner ids (a, b, c, d as above): the part of the cell inside the disc, cut into its four
// quarters; each corner inside the disc takes its own quarter, and the quarters of the corners
// outside are shared equally by those inside. A cell that meets the disc has a corner inside
// (its corner nearest the centre is its point nearest the centre, the origin being a lattice
// point), so the areas add up to the disc's area πR².
void AddCircleCellArea(const std::array<int, 4>& corners, double x0, double y0, double s,
                       double radius, Mesh* mesh) {
  const int present = std::count_if(corners.begin(), corners.end(), [](int v) { return v >= 0; });
  if (present == 0) return;
  if (present == 4) {
    for (int v : corners) mesh->area[v] += 0.25 * s * s;
    return;
  }
  const double h = 0.5 * s;
  const std::array<std::array<double, 2>, 4> quarter{
      {{x0, y0}, {x0 + h, y0}, {x0 + h, y0 + h}, {x0, y0 + h}}};
  double orphaned = 0.0;
  for (int k = 0; k < 4; ++k) {
    const double area = DiscAreaInRectangle(radius, quarter[k][0], quarter[k][0] + h, quarter[k][1],
                                            quarter[k][1] + h);
    if (corners[k] >= 0) {
      mesh->area[corners[k]] += area;
    } else {
      orphaned += area;
    }
  }
  for (int v : corners) {
    if (v >= 0) mesh->area[v] += orphaned / present;
  }
}

// The springs from lattice node (i, j) of a circle mesh (`at`: lattice (i, j) to node id, -1
// outside the disc).
template <typename At>
void AddCircleLinks(int i, int j, const At& at, Mesh* mesh) {
  const int a = at(i, j);
  if (a >= 0 && at(i + 1, j) >= 0) mesh->warp.push_back({a, at(i + 1, j)});
  if (a >= 0 && at(i, j + 1) >= 0) mesh->weft.push_back({a, at(i, j + 1)});
  if (a >= 0 && at(i + 2, j) >= 0) mesh->flexion_warp.push_back({a, at(i + 2, j)});
  if (a >= 0 && at(i, j + 2) >= 0) mesh->flexion_weft.push_back({a, at(i, j + 2)});
  if (a >= 0 && at(i + 1, j + 1) >= 0) mesh->shear.push_back({a, at(i + 1, j + 1)});
  if (at(i + 1, j) >= 0 && at(i, j + 1) >= 0) mesh->shear.push_back({at(i + 1, j), at(i, j + 1)});
}

// The fringe of a circle mesh (struct Fringe): along each outline edge (a, b) of the triangles, a
// strip out to the circle, cut into pieces spanning at most kFringeArc radians so that the
// chords' shortfall against the arc, R²(φ − sin φ)/2 per piece, stays below 2e-5 of πR².
constexpr double kFringeArc = 0.01;

using Weights = std::vector<std::pair<int, double>>;

// Weights of x_b + J_b d, with J_b the least-squares deformation gradient of node b over the nodes
// it shares a triangle with, and d a flat (x, y) offset from b: exact for affine maps.
class BoundaryGradient {
 public:
  BoundaryGradient(const Mesh& mesh, int b, const std::vector<int>& neighbours)
      : b_(b), neighbours_(neighbours) {
    Eigen::Matrix2d moment = Eigen::Matrix2d::Zero();
    for (int n : neighbours_) {
      const Eigen::Vector2d d = (mesh.nodes[n] - mesh.nodes[b]).head<2>();
      differences_.push_back(d);
      moment += d * d.transpose();
    }
    inverse_ = moment.inverse();  // a triangle's two other corners are not collinear with b
  }
  // Adds `scale` × the weights of x_b + J_b offset to `weights`.
  void Add(const Eigen::Vector2d& offset, double scale, Weights* weights) const {
    const Eigen::Vector2d solved = inverse_ * offset;
    double sum = 0.0;
    for (size_t k = 0; k < neighbours_.size(); ++k) {
      const double w = differences_[k].dot(solved);
      weights->push_back({neighbours_[k], scale * w});
      sum += w;
    }
    weights->push_back({b_, scale * (1.0 - sum)});
  }

 private:
  int b_;
  std::vector<int> neighbours_;
  std::vector<Eigen::Vector2d> differences_;
  Eigen::Matrix2d inverse_;
};

// The triangles' outline edges (in one triangle only), oriented as in that triangle.
std::vector<Link> OutlineEdges(const Mesh& mesh) {
  std::map<Link, int> count;
  for (const auto& t : mesh.triangles) {
    for (int e = 0; e < 3; ++e) ++count[Ordered(t[e], t[(e + 1) % 3])];
  }
  std::vector<Link> outline;
  for (const auto& t : mesh.triangles) {
    for (int e = 0; e < 3; ++e) {
      if (count[Ordered(t[e], t[(e + 1) % 3])] == 1) outline.push_back({t[e], t[(e + 1) % 3]});
    }
  }
  return outline;
}

void AddFringe(const Eigen::Vector3d& centre, double radius, Mesh* mesh) {
  const int n = static_cast<int>(mesh->nodes.size());
  std::vector<std::set<int>> neighbours(n);
  for (const auto& t : mesh->triangles) {
    for (int e = 0; e < 3; ++e) {
      neighbours[t[e]].insert({t[(e + 1) % 3], t[(e + 2) % 3]});
    }
  }
  std::map<int, BoundaryGradient> gradient;
  auto gradient_at = [&](int b) -> const BoundaryGradient& {
    auto found = gradient.find(b);
    if (found == gradient.end()) {
      const std::vector<int> around(neighbours[b].begin(), neighbours[b].end());
      found = gradient.emplace(b, BoundaryGradient(*mesh, b, around)).first;
    }
    return found->second;
  };
  auto flat = [&](int v) { return Eigen::Vector2d((mesh->nodes[v] - centre).head<2>()); };
  Fringe& fringe = mesh->fringe;
  auto add_point = [&](Weights weights) {
    fringe.points.push_back(std::move(weights));
    return n + static_cast<int>(fringe.points.size()) - 1;
  };
  auto angle_of = [&](int v) { return std::atan2(flat(v).y(), flat(v).x()); };
  auto on_circle = [&](double angle) {
    return Eigen::Vector2d(radius * Eigen::Vector2d(std::cos(angle), std::sin(angle)));
  };
  // The circle point of an outline node, shared by the two outline edges that meet there.
  std::map<int, int> outer_of_node;
  auto node_outer = [&](int v) {
    auto found = outer_of_node.find(v);
    if (found != outer_of_node.end()) return found->second;
    Weights outer;
    gradient_at(v).Add(on_circle(angle_of(v)) - flat(v), 1.0, &outer);
    return outer_of_node[v] = add_point(std::move(outer));
  };
  for (const Link& edge : OutlineEdges(*mesh)) {
    const int a = edge[0], b = edge[1];
    const double from = angle_of(a);
    const double span = std::remainder(angle_of(b) - from, 2.0 * M_PI);
    const int pieces = std::max(1, static_cast<int>(std::ceil(std::abs(span) / kFringeArc)));
    int inner_before = a, outer_before = node_outer(a);
    for (int i = 1; i <= pieces; ++i) {
      const double t = static_cast<double>(i) / pieces;
      int outer_id, inner_id;
      if (i == pieces) {
        outer_id = node_outer(b), inner_id = b;
      } else {
        const Eigen::Vector2d offset =
            on_circle(from + t * span) - ((1.0 - t) * flat(a) + t * flat(b));
        Weights outer;
        gradient_at(a).Add(offset, 1.0 - t, &outer);
        gradient_at(b).Add(offset, t, &outer);
        outer_id = add_point(std::move(outer));
        inner_id = add_point({{a, 1.0 - t}, {b, t}});
      }
      fringe.triangles.push_back({inner_before, inner_id, outer_id});
      fringe.triangles.push_back({inner_before, outer_id, outer_before});
      inner_before = inner_id, outer_before = outer_id;
    }
  }
}

Mesh BuildCircle(const MeshSpec& spec) {
  if (!(spec.radius > 0.0) || !(spec.spacing > 0.0)) {
    throw InputError(spec.where, "a circle mesh needs a positive radius and spacing");
  }
  const double rho = spec.radius / spec.spacing;  // radius in lattice steps
  const int m = static_cast<int>(std::floor(rho * (1.0 + 1e-9)));
  // The loader caps the lattice (mesh.max_nodes ≤ 1e8 ⇒ side ≤ 10⁴); the index is size_t anyway.
  assert(rho < 1e5 && "a circle lattice beyond the loader's mesh.max_nodes");
  const int side = 2 * m + 1;
  const double limit = rho * rho * (1.0 + 1e-9);
  Mesh mesh;
  mesh.nu = mesh.nv = side;
  std::vector<int> id(static_cast<size_t>(side) * side, -1);
  auto index = [side](int i, int j) { return static_cast<size_t>(j) * side + i; };
  auto at = [&](int i, int j) {  // lattice (i, j) in [0, side)², -1 outside
    return (i < 0 || j < 0 || i >= side || j >= side) ? -1 : id[index(i, j)];
  };
  for (int j = 0; j < side; ++j) {
    for (int i = 0; i < side; ++i) {
      const double x = i - m, y = j - m;
      if (x * x + y * y > limit) continue;
      id[index(i, j)] = static_cast<int>(mesh.nodes.size());
      mesh.nodes.push_back(spec.origin + spec.spacing * Eigen::Vector3d(x, y, 0.0));
      mesh.grid_index.push_back({i, j});
    }
  }
  mesh.area.assign(mesh.nodes.size(), 0.0);
  for (int j = 0; j < side; ++j) {
    for (int i = 0; i < side; ++i) {
      AddCircleLinks(i, j, at, &mesh);
      AddCircleCellTriangles(at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1), &mesh);
    }
  }
  // Cells from one step outside the lattice's first row and column: the disc reaches past it.
  for (int j = -1; j < side; ++j) {
    for (int i = -1; i < side; ++i) {
      AddCircleCellArea({at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)},
                        (i - m) * spec.spacing, (j - m) * spec.spacing, spec.spacing, spec.radius,
                        &mesh);
    }
  }
  AddFringe(spec.origin, spec.radius, &mesh);
  return mesh;
}

// ---------------------------------------------------------------------------------------------
// arc

// Adds link {a, b} to `links` unless it is there already (in either order).
void AddUnique(int a, int b, std::set<Link>* seen, std::vector<Link>* links) {
  if (seen->insert(Ordered(a, b)).second) links->push_back({a, b});
}

Mesh BuildArc(const MeshSpec& spec) {
  // The loader owns these ranges (mesh.spokes ≥ 3, rings ≥ 1, rings × spokes ≤ mesh.max_nodes).
  assert(spec.radius > 0.0 && spec.rings >= 1 && spec.spokes >= 3);
  const int rings = spec.rings, spokes = spec.spokes;
  auto id = [spokes](int ring, int spoke) {  // ring 0 is the centre
    return ring == 0 ? 0 : 1 + (ring - 1) * spokes + (spoke % spokes);
  };
  Mesh mesh;
  mesh.nodes.push_back(spec.origin);
  for (int r = 1; r <= rings; ++r) {
    const double radius = spec.radius * r / rings;
    for (int k = 0; k < spokes; ++k) {
      const double angle = 2.0 * M_PI * k / spokes;
      mesh.nodes.push_back(spec.origin +
                           radius * Eigen::Vector3d(std::cos(angle), std::sin(angle), 0.0));
    }
  }
  mesh.grid_index.assign(mesh.nodes.size(), {-1, -1});
  std::set<Link> seen_weft, seen_flexion_warp, seen_flexion_weft;
  for (int k = 0; k < spokes; ++k) {
    for (int r = 0; r < rings; ++r) mesh.warp.push_back({id(r, k), id(r + 1, k)});
    for (int r = 0; r + 2 <= rings; ++r) {
      AddUnique(id(r, k), id(r + 2, k), &seen_flexion_warp, &mesh.flexion_warp);
    }
    // Along a diameter, through the centre (opposite spokes).
    if (spokes % 2 == 0 && k < spokes / 2) {
      AddUnique(id(1, k), id(1, k + spokes / 2), &seen_flexion_warp, &mesh.flexion_warp);
    }
    mesh.triangles.push_back({0, id(1, k), id(1, k + 1)});
    for (int r = 1; r <= rings; ++r) {
      AddUnique(id(r, k), id(r, k + 1), &seen_weft, &mesh.weft);
      AddUnique(id(r, k), id(r, k + 2), &seen_flexion_weft, &mesh.flexion_weft);
      if (r < rings) {
        mesh.shear.push_back({id(r, k), id(r + 1, k + 1)});
        mesh.shear.push_back({id(r, k + 1), id(r + 1, k)});
        mesh.triangles.push_back({id(r, k), id(r + 1, k), id(r + 1, k + 1)});
        mesh.triangles.push_back({id(r, k), id(r + 1, k + 1), id(r, k + 1)});
      }
    }
  }
  LumpTriangleAreas(&mesh);
  return mesh;
}

// ---------------------------------------------------------------------------------------------
// file

// The label of a mesh given as arrays, in its errors.
constexpr const char* kMeshArrays = "mesh arrays";

// A file's error at its place; an array's at the face (FilePlace::line = face + 1) or as a whole.
[[noreturn]] void FileError(const MeshSpec& spec, const FilePlace& place, const std::string& what) {
  if (spec.arrays) {
    throw InputError(
        Location{kMeshArrays, 0, 0,
                 place.line > 0 ? "faces[" + std::to_string(place.line - 1) + "]" : ""},
        what);
  }
  throw InputError(spec.where, PlaceText(spec.path, place) + ": " + what);
}

// A vertex's number as the user counts it: from 1 in a file, from 0 in an array.
std::string VertexNumber(const MeshSpec& spec, int v) {
  return std::to_string(spec.arrays ? v : v + 1);
}

std::string CountedFrom(const MeshSpec& spec) {
  return spec.arrays ? "the array has " : "the file has ";
}

// A face of zero area gives its nodes no mass and no membrane: an error, located at its line.
void CheckFaceAreas(const MeshFileData& data, const Mesh& mesh, const MeshSpec& spec) {
  const double size = BoundingDiagonal(AsColumns(mesh.nodes));
  for (size_t f = 0; f < data.faces.size(); ++f) {
    const auto& face = data.faces[f];
    Eigen::Vector3d twice_area = Eigen::Vector3d::Zero();  // the fan's summed cross products
    const Eigen::Vector3d& first = mesh.nodes[face[0]];
    for (size_t k = 1; k + 1 < face.size(); ++k) {
      twice_area += (mesh.nodes[face[k]] - first).cross(mesh.nodes[face[k + 1]] - first);
    }
    if (!(twice_area.norm() > 1e-12 * size * size)) {
      FileError(spec, data.face_places[f], "a face has zero area (its vertices are collinear)");
    }
  }
}

// Triangulates the faces (fans), checking every index; fills nodes, triangles, springs, areas.
Mesh SurfaceMesh(const MeshFileData& data, const MeshSpec& spec) {
  if (data.vertices.size() > static_cast<size_t>(spec.max_nodes)) {
    FileError(spec, {},
              CountedFrom(spec) + std::to_string(data.vertices.size()) +
                  " vertices, above the limit of " + std::to_string(spec.max_nodes) +
                  " nodes; raise mesh.max_nodes to build it anyway");
  }
  const int n = static_cast<int>(data.vertices.size());
  if (n == 0) FileError(spec, {}, CountedFrom(spec) + "no vertices");
  if (data.faces.empty()) {
    FileError(spec, {}, CountedFrom(spec) + "no faces (springs follow face edges)");
  }
  Mesh mesh;
  mesh.nodes = data.vertices;
  mesh.grid_index.assign(n, {-1, -1});
  std::vector<char> used(n, 0);
  for (size_t f = 0; f < data.faces.size(); ++f) {
    const auto& face = data.faces[f];
    const FilePlace& line = data.face_places[f];
    if (face.size() < 3) FileError(spec, line, "a face needs at least 3 vertices");
    std::set<int> distinct;
    for (int v : face) {
      if (v < 0 || v >= n) {
        FileError(spec, line,
                  "face vertex " + VertexNumber(spec, v) + " is out of range (" +
                      CountedFrom(spec) + std::to_string(n) + " vertices, counted from " +
                      (spec.arrays ? "0" : "1") + ")");
      }
      if (!distinct.insert(v).second) {
        FileError(spec, line, "a face uses vertex " + VertexNumber(spec, v) + " twice");
      }
      used[v] = 1;
    }
    for (size_t k = 1; k + 1 < face.size(); ++k) {
      mesh.triangles.push_back({face[0], face[k], face[k + 1]});
    }
  }
  for (int v = 0; v < n; ++v) {
    if (!used[v]) {
      FileError(spec, {},
                "vertex " + VertexNumber(spec, v) + " belongs to no face (it would float free)");
    }
  }
  // Edges and, for each, the vertices opposite it in the triangles that share it.
  std::map<Link, std::vector<int>> opposite;
  for (const auto& t : mesh.triangles) {
    for (int e = 0; e < 3; ++e) opposite[Ordered(t[e], t[(e + 1) % 3])].push_back(t[(e + 2) % 3]);
  }
  std::set<Link> flexion;
  for (const auto& [edge, vertices] : opposite) {
    mesh.warp.push_back(edge);
    for (size_t a = 0; a < vertices.size(); ++a) {
      for (size_t b = a + 1; b < vertices.size(); ++b) {
        if (vertices[a] != vertices[b]) flexion.insert(Ordered(vertices[a], vertices[b]));
      }
    }
  }
  mesh.flexion_warp.assign(flexion.begin(), flexion.end());
  LumpTriangleAreas(&mesh);
  CheckFaceAreas(data, mesh, spec);
  return mesh;
}

// The arrays as a file's contents: each face's place is its row (line = row + 1).
MeshFileData DataOfArrays(const MeshSpec::Arrays& arrays) {
  MeshFileData data;
  data.vertices = arrays.vertices;
  data.faces = arrays.faces;
  for (size_t f = 0; f < arrays.faces.size(); ++f) {
    data.face_places.push_back(FilePlace{static_cast<int>(f) + 1, -1});
  }
  return data;
}

Mesh BuildFromFile(const MeshSpec& spec) {
  if (spec.arrays) return SurfaceMesh(DataOfArrays(*spec.arrays), spec);
  try {
    return SurfaceMesh(ReadMeshFile(spec.path), spec);
  } catch (const MeshFileError& error) {
    throw InputError(spec.where, error.what());
  }
}

// ---------------------------------------------------------------------------------------------
// checks for every kind

// Two nodes closer than 1e-12 × the mesh size: a duplicated vertex or a zero-length spring.
// Nodes are hashed into cubes of that side, so two that close lie in the same or neighbouring
// cubes: linear in the nodes. (Sorting along one axis and comparing the nodes close along it was
// quadratic in a grid's column: 8.8 s for a 834 × 834 grid.)
void CheckNoCoincidentNodes(const Mesh& mesh, const Location& where) {
  const auto& p = mesh.nodes;
  const double tolerance = 1e-12 * BoundingDiagonal(AsColumns(p));
  auto report = [&](int a, int b) {
    throw InputError(where, "nodes " + std::to_string(std::min(a, b)) + " and " +
                                std::to_string(std::max(a, b)) +
                                " coincide (a duplicated vertex or a zero-length spring)");
  };
  if (!(tolerance > 0.0)) report(0, 1);  // every node at one point (the mesh has ≥ 2)
  Eigen::Vector3d low = p[0];
  for (const auto& q : p) low = low.cwiseMin(q);
  using Cell = std::array<long long, 3>;
  struct CellHash {  // unsigned: wraps, never overflows
    size_t operator()(const Cell& c) const {
      const auto u = [](long long v) { return static_cast<unsigned long long>(v); };
      return std::hash<unsigned long long>()(u(c[0]) * 73856093ULL ^ u(c[1]) * 19349663ULL ^
                                             u(c[2]) * 83492791ULL);
    }
  };
  std::unordered_multimap<Cell, int, CellHash> cells;
  cells.reserve(p.size());
  for (int k = 0; k < static_cast<int>(p.size()); ++k) {
    Cell cell;  // (p − low) / tolerance ≤ 1e12 per axis: fits
    for (int c = 0; c < 3; ++c) cell[c] = static_cast<long long>((p[k][c] - low[c]) / tolerance);
    for (long long dx = -1; dx <= 1; ++dx) {
      for (long long dy = -1; dy <= 1; ++dy) {
        for (long long dz = -1; dz <= 1; ++dz) {
          const auto range = cells.equal_range({cell[0] + dx, cell[1] + dy, cell[2] + dz});
          for (auto it = range.first; it != range.second; ++it) {
            if ((p[it->second] - p[k]).norm() <= tolerance) report(it->second, k);
          }
        }
      }
    }
    cells.emplace(cell, k);
  }
}

}  // namespace

std::vector<double> WithFringePoints(const Fringe& fringe, const std::vector<double>& positions) {
  std::vector<double> all(positions);
  all.reserve(positions.size() + 3 * fringe.points.size());
  for (const auto& weights : fringe.points) {
    Eigen::Vector3d point = Eigen::Vector3d::Zero();
    for (const auto& [node, weight] : weights) {
      point += weight * Eigen::Vector3d(positions[3 * node], positions[3 * node + 1],
                                        positions[3 * node + 2]);
    }
    all.insert(all.end(), point.data(), point.data() + 3);
  }
  return all;
}

double BoundingDiagonal(const Eigen::Ref<const Eigen::Matrix3Xd>& points) {
  if (points.cols() == 0) return 0.0;
  return (points.rowwise().maxCoeff() - points.rowwise().minCoeff()).norm();
}

Mesh BuildMesh(const MeshSpec& spec) {
  Mesh mesh;
  switch (spec.kind) {
    case MeshSpec::Kind::kGrid:
      mesh = BuildGrid(spec);
      break;
    case MeshSpec::Kind::kChain:
      mesh = BuildChain(spec);
      break;
    case MeshSpec::Kind::kCircle:
      mesh = BuildCircle(spec);
      break;
    case MeshSpec::Kind::kArc:
      mesh = BuildArc(spec);
      break;
    case MeshSpec::Kind::kFile:
      mesh = BuildFromFile(spec);
      break;
  }
  if (mesh.nodes.size() < 2) {
    throw InputError(spec.where, "the mesh has " + std::to_string(mesh.nodes.size()) +
                                     " node(s); at least 2 are needed");
  }
  CheckNoCoincidentNodes(mesh, spec.where);
  return mesh;
}

}  // namespace drape
