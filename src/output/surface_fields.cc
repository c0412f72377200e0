#include "src/output/surface_fields.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

namespace drape {

double TriangleArea(const std::vector<double>& positions, const std::array<int, 3>& t) {
  const Eigen::Vector3d a = NodeAt(positions, t[0]), b = NodeAt(positions, t[1]),
                        c = NodeAt(positions, t[2]);
  return 0.5 * (b - a).cross(c - a).norm();
}

std::vector<Eigen::Vector3d> VertexNormals(const Model& model) {
  std::vector<Eigen::Vector3d> normals(model.num_nodes, Eigen::Vector3d::Zero());
  for (const auto& t : model.triangles) {
    const Eigen::Vector3d a = model.position(t[0]), b = model.position(t[1]),
                          c = model.position(t[2]);
    const Eigen::Vector3d n = (b - a).cross(c - a);  // twice the area, along the normal
    for (int v : t) normals[v] += n;
  }
  for (auto& n : normals) {
    if (n.norm() > 0.0) n.normalize();
  }
  return normals;
}

std::vector<std::array<double, 2>> PatternCoordinates(const Model& model) {
  const bool known = model.initial.size() == model.positions.size();
  const std::vector<double>& start = known ? model.initial : model.positions;
  Eigen::Vector3d low = Eigen::Vector3d::Constant(INFINITY), high = -low;
  for (int node = 0; node < model.num_nodes; ++node) {
    const Eigen::Vector3d p = NodeAt(start, node);
    low = low.cwiseMin(p);
    high = high.cwiseMax(p);
  }
  const Eigen::Vector3d extent = high - low;
  int narrowest = 0;
  extent.minCoeff(&narrowest);
  const int u = narrowest == 0 ? 1 : 0, v = narrowest == 2 ? 1 : 2;
  const double scale = std::max({extent[u], extent[v], 1e-300});
  std::vector<std::array<double, 2>> uv;
  uv.reserve(model.num_nodes);
  for (int node = 0; node < model.num_nodes; ++node) {
    const auto p = NodeAt(start, node);
    uv.push_back({(p[u] - low[u]) / scale, (p[v] - low[v]) / scale});
  }
  return uv;
}

std::vector<double> VertexAreaStretch(const Model& model) {
  std::vector<double> now(model.num_nodes, 0.0), start(model.num_nodes, 0.0);
  if (model.initial.size() != model.positions.size()) return now;
  for (const auto& t : model.triangles) {
    const double area = TriangleArea(model.positions, t), rest = TriangleArea(model.initial, t);
    for (int v : t) {
      now[v] += area;
      start[v] += rest;
    }
  }
  std::vector<double> stretch(model.num_nodes, 0.0);
  for (int k = 0; k < model.num_nodes; ++k) {
    if (start[k] > 0.0) stretch[k] = now[k] / start[k] - 1.0;
  }
  return stretch;
}

}  // namespace drape
