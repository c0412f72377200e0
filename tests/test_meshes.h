// Meshes the tests build: closed surfaces for the mesh obstacles (an icosphere, a cuboid, their OBJ
// files), and two squares that cross each other.
#ifndef DRAPE_TESTS_TEST_MESHES_H_
#define DRAPE_TESTS_TEST_MESHES_H_

#include <Eigen/Core>
#include <array>
#include <cmath>
#include <fstream>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "src/geometry/triangle_surface.h"

namespace drape::testing {

// A sphere of `radius` about the origin: an icosahedron whose faces are split in four `level`
// times (20 · 4^level triangles), every vertex on the sphere; faces outward.
inline std::pair<std::vector<Eigen::Vector3d>, std::vector<std::array<int, 3>>> IcosphereMesh(
    double radius, int level) {
  const double t = (1.0 + std::sqrt(5.0)) / 2.0;
  std::vector<Eigen::Vector3d> v = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0},
                                    {0, -1, t}, {0, 1, t}, {0, -1, -t}, {0, 1, -t},
                                    {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
  for (auto& p : v) p.normalize();
  std::vector<std::array<int, 3>> faces = {
      {0, 11, 5},  {0, 5, 1},  {0, 1, 7},  {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
      {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
      {3, 8, 9},   {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
  for (int l = 0; l < level; ++l) {
    std::map<std::pair<int, int>, int> middle;
    auto midpoint = [&](int a, int b) {
      const auto key = std::minmax(a, b);
      auto [at, inserted] = middle.insert({{key.first, key.second}, 0});
      if (inserted) {
        v.push_back((v[a] + v[b]).normalized());
        at->second = static_cast<int>(v.size()) - 1;
      }
      return at->second;
    };
    std::vector<std::array<int, 3>> split;
    for (const auto& [a, b, c] : faces) {
      const int ab = midpoint(a, b), bc = midpoint(b, c), ca = midpoint(c, a);
      split.insert(split.end(), {{a, ab, ca}, {b, bc, ab}, {c, ca, bc}, {ab, bc, ca}});
    }
    faces = std::move(split);
  }
  for (auto& p : v) p *= radius;
  return {v, faces};
}

inline std::shared_ptr<const TriangleSurface> Icosphere(double radius, int level) {
  auto [vertices, faces] = IcosphereMesh(radius, level);
  return TriangleSurface::Make(std::move(vertices), std::move(faces));
}

// The box [low, high] as 12 triangles (each face split along a diagonal), normals outward.
inline std::shared_ptr<const TriangleSurface> Cuboid(const Eigen::Vector3d& low,
                                                     const Eigen::Vector3d& high) {
  std::vector<Eigen::Vector3d> corners;
  corners.reserve(8);
  for (int k = 0; k < 8; ++k) {
    corners.emplace_back(k & 1 ? high.x() : low.x(), k & 2 ? high.y() : low.y(),
                         k & 4 ? high.z() : low.z());
  }
  return TriangleSurface::Make(corners, {{0, 2, 3},
                                         {0, 3, 1},
                                         {4, 5, 7},
                                         {4, 7, 6},
                                         {0, 1, 5},
                                         {0, 5, 4},
                                         {2, 6, 7},
                                         {2, 7, 3},
                                         {0, 4, 6},
                                         {0, 6, 2},
                                         {1, 3, 7},
                                         {1, 7, 5}});
}

// Writes the icosphere as an OBJ file at `path`.
inline void WriteIcosphereObj(const std::string& path, double radius, int level) {
  const auto [vertices, faces] = IcosphereMesh(radius, level);
  std::ofstream out(path);
  out.precision(17);
  for (const auto& p : vertices) out << "v " << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
  for (const auto& f : faces) out << "f " << f[0] + 1 << ' ' << f[1] + 1 << ' ' << f[2] + 1 << '\n';
}

// Two 3 × 3-node squares of one OBJ file, each to be held by its border: one flat in z = 0 with
// 0.5 m cells, one standing across it in x = 0.7 (src/model/self_intersection.h finds them
// crossing). Their border nodes are every id but 4 and 13.
inline std::string CrossedSquaresObj() {
  std::string obj;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j)
      obj += "v " + std::to_string(0.5 * i) + " " + std::to_string(0.5 * j) + " 0\n";
  }
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j)
      obj +=
          "v 0.7 " + std::to_string(0.1 + 0.25 * i) + " " + std::to_string(-0.5 + 0.5 * j) + "\n";
  }
  for (int base : {1, 10}) {  // OBJ counts from 1; the squares' first nodes
    for (int i = 0; i < 2; ++i) {
      for (int j = 0; j < 2; ++j) {
        const int a = base + 3 * i + j, b = a + 3, c = a + 4, d = a + 1;
        obj += "f " + std::to_string(a) + " " + std::to_string(b) + " " + std::to_string(c) +
               "\nf " + std::to_string(a) + " " + std::to_string(c) + " " + std::to_string(d) +
               "\n";
      }
    }
  }
  return obj;
}

// A spring scene of the crossed squares (CrossedSquaresObj in `obj_path`), held by their borders
// under gravity: it converges to a state that passes through itself.
inline std::string CrossedSquaresScene(const std::string& obj_path) {
  return "name: crossed\nmesh: {kind: file, path: " + obj_path +
         "}\n"
         "material:\n  model: springs\n  density: 0.2\n"
         "  springs: {structural: 1000}\n"
         "fixed:\n  - nodes: {ids: [0, 1, 2, 3, 5, 6, 7, 8, 9, 10, 11, 12, 14, "
         "15, 16, 17]}\n"
         "loads: {gravity: [0, 0, -9.81]}\n"
         "solver: {method: newton, tolerance: 1.0e-9}\n"
         "output: {directory: out, write: [summary]}\n";
}

}  // namespace drape::testing

#endif  // DRAPE_TESTS_TEST_MESHES_H_
