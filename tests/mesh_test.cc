#include "src/model/mesh.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <array>
#include <cmath>
#include <numeric>
#include <regex>
#include <set>
#include <string>

#include "tests/source_lines.h"
#include "tests/test_paths.h"

namespace drape {
namespace mesh_test {

Location SceneLocation() { return Location{"scene.yaml", 3, 5, "mesh"}; }

// The program asks a mesh's kind what to do by a switch over MeshSpec::Kind without a default,
// never by == or !=, so that the compiler (-Wswitch, in -Wall) names every place a new kind has to
// be handled.
TEST(MeshKinds, EveryDispatchOnTheKindIsASwitch) {
  testing::ExpectEveryDispatchIsASwitch("MeshSpec::Kind");
}

MeshSpec GridSpec(int nu, int nv, double width, double height) {
  MeshSpec spec;
  spec.kind = MeshSpec::Kind::kGrid;
  spec.nodes = {nu, nv};
  spec.size = {width, height};
  spec.where = SceneLocation();
  return spec;
}

MeshSpec FileSpec(const std::string& name) {
  MeshSpec spec;
  spec.kind = MeshSpec::Kind::kFile;
  spec.path = std::string(drape_tests::kSourceDir) + "/tests/data/meshes/" + name;
  spec.where = SceneLocation();
  return spec;
}

double Sum(const std::vector<double>& values) {
  return std::accumulate(values.begin(), values.end(), 0.0);
}

double LinkLength(const Mesh& mesh, const Link& link) {
  return (mesh.nodes[link[1]] - mesh.nodes[link[0]]).norm();
}

// The message of the InputError that `build` throws ("" if none).
template <typename Build>
std::string ErrorOf(Build build) {
  try {
    build();
  } catch (const InputError& error) {
    return error.what();
  }
  return "";
}

TEST(Mesh, GridNodeIdsAndPositions) {
  const int nu = 4, nv = 3;
  MeshSpec spec = GridSpec(nu, nv, 0.3, 0.4);
  spec.origin = {1.0, 2.0, 3.0};
  const Mesh mesh = BuildMesh(spec);
  ASSERT_EQ(mesh.nodes.size(), static_cast<size_t>(nu * nv));
  EXPECT_EQ(mesh.nu, nu);
  EXPECT_EQ(mesh.nv, nv);
  for (int j = 0; j < nv; ++j) {
    for (int i = 0; i < nu; ++i) {
      const int id = j * nu + i;
      EXPECT_EQ(mesh.grid_index[id], (std::array<int, 2>{i, j}));
      const Eigen::Vector3d expected =
          spec.origin + Eigen::Vector3d(0.3 * i / (nu - 1), 0.4 * j / (nv - 1), 0.0);
      EXPECT_NEAR((mesh.nodes[id] - expected).norm(), 0.0, 1e-15) << "node " << id;
    }
  }
}

TEST(Mesh, GridLinkCountsFollowTheFormulas) {
  const int nu = 5, nv = 4;
  const Mesh mesh = BuildMesh(GridSpec(nu, nv, 0.8, 0.6));
  EXPECT_EQ(mesh.warp.size(), static_cast<size_t>((nu - 1) * nv));
  EXPECT_EQ(mesh.weft.size(), static_cast<size_t>(nu * (nv - 1)));
  EXPECT_EQ(mesh.shear.size(), static_cast<size_t>(2 * (nu - 1) * (nv - 1)));
  EXPECT_EQ(mesh.flexion_warp.size(), static_cast<size_t>((nu - 2) * nv));
  EXPECT_EQ(mesh.flexion_weft.size(), static_cast<size_t>(nu * (nv - 2)));
  EXPECT_EQ(mesh.triangles.size(), static_cast<size_t>(2 * (nu - 1) * (nv - 1)));
  const double du = 0.8 / (nu - 1), dv = 0.6 / (nv - 1);
  for (const Link& link : mesh.warp) EXPECT_NEAR(LinkLength(mesh, link), du, 1e-15);
  for (const Link& link : mesh.weft) EXPECT_NEAR(LinkLength(mesh, link), dv, 1e-15);
  for (const Link& link : mesh.shear)
    EXPECT_NEAR(LinkLength(mesh, link), std::hypot(du, dv), 1e-15);
  for (const Link& link : mesh.flexion_warp) EXPECT_NEAR(LinkLength(mesh, link), 2 * du, 1e-15);
  for (const Link& link : mesh.flexion_weft) EXPECT_NEAR(LinkLength(mesh, link), 2 * dv, 1e-15);
}

TEST(Mesh, UniformGridAreasAreQuarterCellsAtCornersHalfOnEdges) {
  const int nu = 4, nv = 3;
  const double width = 0.9, height = 0.4;
  const Mesh mesh = BuildMesh(GridSpec(nu, nv, width, height));
  const double cell = width / (nu - 1) * height / (nv - 1);
  EXPECT_NEAR(Sum(mesh.area), width * height, 1e-15);
  EXPECT_NEAR(mesh.area[0], cell / 4, 1e-15);            // corner (0, 0)
  EXPECT_NEAR(mesh.area[1], cell / 2, 1e-15);            // bottom edge (1, 0)
  EXPECT_NEAR(mesh.area[1 * nu + 1], cell, 1e-15);       // interior (1, 1)
  EXPECT_NEAR(mesh.area[nu * nv - 1], cell / 4, 1e-15);  // corner (nu-1, nv-1)
}

TEST(Mesh, NonUniformGridUsesTheGivenCoordinates) {
  MeshSpec spec = GridSpec(0, 0, 0.0, 0.0);
  spec.u = {0.0, 0.1, 0.3, 0.6};
  spec.v = {0.0, 0.2, 0.25};
  const Mesh mesh = BuildMesh(spec);
  ASSERT_EQ(mesh.nu, 4);
  ASSERT_EQ(mesh.nv, 3);
  for (int j = 0; j < 3; ++j) {
    for (int i = 0; i < 4; ++i) {
      EXPECT_EQ(mesh.nodes[j * 4 + i], Eigen::Vector3d(spec.u[i], spec.v[j], 0.0));
    }
  }
  EXPECT_NEAR(Sum(mesh.area), (0.6 - 0.0) * (0.25 - 0.0), 1e-15);
  // Node (1, 1) touches four cells of different sizes: a quarter of each.
  const double expected = 0.25 * (0.1 + 0.2) * (0.2 + 0.05);
  EXPECT_NEAR(mesh.area[1 * 4 + 1], expected, 1e-15);
}

TEST(Mesh, NonIncreasingCoordinatesAreRejected) {
  MeshSpec spec = GridSpec(3, 3, 1.0, 1.0);
  spec.u = {0.0, 0.2, 0.2};
  EXPECT_NE(ErrorOf([&] { BuildMesh(spec); }).find("strictly increasing"), std::string::npos);
}

TEST(Mesh, PlaneXzStandsTheGridUp) {
  MeshSpec spec = GridSpec(3, 2, 0.4, 0.3);
  spec.plane = "xz";
  spec.origin = {0.0, 0.5, 1.0};
  const Mesh mesh = BuildMesh(spec);
  for (int j = 0; j < 2; ++j) {
    for (int i = 0; i < 3; ++i) {
      const Eigen::Vector3d& p = mesh.nodes[j * 3 + i];
      EXPECT_NEAR(p.x(), 0.2 * i, 1e-15);
      EXPECT_EQ(p.y(), 0.5);
      EXPECT_NEAR(p.z(), 1.0 + 0.3 * j, 1e-15);
    }
  }
  EXPECT_NEAR(Sum(mesh.area), 0.4 * 0.3, 1e-15);
}

TEST(Mesh, SingleRowHasWarpLinksOnly) {
  const int n = 6;
  const double length = 1.0, width = 0.05;
  const Mesh mesh = BuildMesh(GridSpec(n, 1, length, width));
  EXPECT_EQ(mesh.warp.size(), static_cast<size_t>(n - 1));
  EXPECT_EQ(mesh.flexion_warp.size(), static_cast<size_t>(n - 2));
  EXPECT_TRUE(mesh.weft.empty());
  EXPECT_TRUE(mesh.shear.empty());
  EXPECT_TRUE(mesh.flexion_weft.empty());
  EXPECT_EQ(mesh.lines, mesh.warp);  // drawn as a line: it has no triangles
  // A strip of the given width: length × width in all, half a segment at the ends.
  EXPECT_NEAR(Sum(mesh.area), length * width, 1e-15);
  EXPECT_NEAR(mesh.area[0], 0.5 * length / (n - 1) * width, 1e-15);
}

TEST(Mesh, ChainRunsAlongItsNormalisedDirection) {
  MeshSpec spec;
  spec.kind = MeshSpec::Kind::kChain;
  spec.chain_nodes = 5;
  spec.length = 2.0;
  spec.direction = {0.0, 0.0, -3.0};
  spec.origin = {1.0, 0.0, 0.0};
  const Mesh mesh = BuildMesh(spec);
  ASSERT_EQ(mesh.nodes.size(), 5u);
  const double segment = spec.length / (spec.chain_nodes - 1);
  for (int k = 0; k < 5; ++k) {
    EXPECT_NEAR((mesh.nodes[k] - Eigen::Vector3d(1.0, 0.0, -segment * k)).norm(), 0.0, 1e-15);
  }
  EXPECT_EQ(mesh.warp.size(), 4u);
  EXPECT_EQ(mesh.flexion_warp.size(), 3u);
  EXPECT_EQ(mesh.lines.size(), 4u);
  EXPECT_TRUE(mesh.weft.empty());
  EXPECT_NEAR(Sum(mesh.length), spec.length, 1e-15);
  EXPECT_NEAR(mesh.length[0], segment / 2, 1e-15);
  EXPECT_NEAR(mesh.length[2], segment, 1e-15);
  EXPECT_DOUBLE_EQ(Sum(mesh.area), 0.0);
}

TEST(Mesh, CircleHoldsTheLatticePointsOfTheDisc) {
  MeshSpec spec;
  spec.kind = MeshSpec::Kind::kCircle;
  spec.radius = 0.15;
  spec.spacing = 0.01;
  spec.origin = {0.2, -0.1, 0.5};
  const Mesh mesh = BuildMesh(spec);
  // Count the lattice points inside the disc directly.
  const int m = 15;
  int inside = 0;
  for (int j = -m - 1; j <= m + 1; ++j) {
    for (int i = -m - 1; i <= m + 1; ++i) inside += (i * i + j * j <= m * m) ? 1 : 0;
  }
  EXPECT_EQ(mesh.nodes.size(), static_cast<size_t>(inside));
  EXPECT_EQ(mesh.nu, 2 * m + 1);
  for (size_t k = 0; k < mesh.nodes.size(); ++k) {
    const Eigen::Vector3d offset = mesh.nodes[k] - spec.origin;
    EXPECT_LE(offset.norm(), spec.radius * (1 + 1e-9));
    EXPECT_EQ(offset.z(), 0.0);
    const auto [i, j] = mesh.grid_index[k];
    EXPECT_NEAR(offset.x(), (i - m) * spec.spacing, 1e-15);
    EXPECT_NEAR(offset.y(), (j - m) * spec.spacing, 1e-15);
  }
  for (const Link& link : mesh.warp) EXPECT_NEAR(LinkLength(mesh, link), spec.spacing, 1e-15);
  for (const Link& link : mesh.weft) EXPECT_NEAR(LinkLength(mesh, link), spec.spacing, 1e-15);
  for (double a : mesh.area) EXPECT_GT(a, 0.0);
}

// The lumped areas are the disc cut into the lattice cells: they add up to πR² (to 0.1 %, the
// target; in fact to ~1e-7, the quadrature's error) at every spacing, including spacings that do
// not divide the radius, while the lattice's staircase polygon alone holds 90–97 % of it. An
// interior node keeps one cell, and no rim node takes more than two.
TEST(Mesh, CircleAreasAddUpToTheDisc) {
  for (double radius : {0.15, 0.12, 0.18}) {
    for (double spacing : {0.03, 0.01, 0.007, 0.005, 0.0026}) {
      MeshSpec spec;
      spec.kind = MeshSpec::Kind::kCircle;
      spec.radius = radius;
      spec.spacing = spacing;
      const Mesh mesh = BuildMesh(spec);
      const double disc = M_PI * radius * radius;
      EXPECT_NEAR(Sum(mesh.area), disc, 1e-3 * disc) << radius << " " << spacing;
      EXPECT_NEAR(Sum(mesh.area), disc, 1e-6 * disc) << radius << " " << spacing;
      double polygon = 0.0;
      for (const auto& t : mesh.triangles) {
        polygon +=
            0.5 *
            (mesh.nodes[t[1]] - mesh.nodes[t[0]]).cross(mesh.nodes[t[2]] - mesh.nodes[t[0]]).norm();
      }
      EXPECT_LT(polygon, 0.999 * disc);  // the cut cells are what makes up the difference
      const double cell = spacing * spacing;
      for (size_t k = 0; k < mesh.nodes.size(); ++k) {
        EXPECT_GT(mesh.area[k], 0.0);
        EXPECT_LE(mesh.area[k], 2.0 * cell);
        if (mesh.nodes[k].norm() < radius - 2.0 * spacing) {
          EXPECT_NEAR(mesh.area[k], cell, 1e-15);
        }
      }
    }
  }
}

double TriangleAreas(const std::vector<Eigen::Vector3d>& points,
                     const std::vector<std::array<int, 3>>& triangles) {
  double area = 0.0;
  for (const auto& t : triangles) {
    area += 0.5 * (points[t[1]] - points[t[0]]).cross(points[t[2]] - points[t[0]]).norm();
  }
  return area;
}

std::vector<Eigen::Vector3d> AsPoints(const std::vector<double>& xyz) {
  std::vector<Eigen::Vector3d> points;
  for (size_t k = 0; k < xyz.size(); k += 3) points.emplace_back(xyz[k], xyz[k + 1], xyz[k + 2]);
  return points;
}

std::vector<double> AsXyz(const std::vector<Eigen::Vector3d>& points) {
  std::vector<double> xyz;
  for (const Eigen::Vector3d& p : points) xyz.insert(xyz.end(), {p.x(), p.y(), p.z()});
  return xyz;
}

// The fringe fills the disc beyond the staircase: with it the flat specimen's surface covers πR²
// to 0.1 % (the target; its construction bound is the chords' shortfall, 2e-5, pieces of at most
// 0.01 rad), its outer points lie on the circle, and it adds no area inside the staircase (the
// triangles' areas add up: no overlap). Under an affine map of the specimen (here into a tilted
// plane, sheared and stretched) the fringe's points move with it exactly: on a draped specimen
// they follow the boundary's deformation.
TEST(Mesh, CircleFringeCoversTheDiscBeyondTheStaircaseAndMovesWithAffineMaps) {
  Eigen::Matrix3d map;
  map << 1.1, 0.3, 0.0, -0.2, 0.9, 0.0, 0.4, 0.5, 1.0;
  const Eigen::Vector3d shift(0.3, -0.1, 2.0);
  for (double radius : {0.15, 0.12}) {
    for (double spacing : {0.03, 0.02, 0.01, 0.007, 0.0026}) {
      MeshSpec spec;
      spec.kind = MeshSpec::Kind::kCircle;
      spec.radius = radius;
      spec.spacing = spacing;
      spec.origin = Eigen::Vector3d(0.5, -0.2, 0.1);
      const Mesh mesh = BuildMesh(spec);
      ASSERT_FALSE(mesh.fringe.triangles.empty());
      const auto flat = AsPoints(WithFringePoints(mesh.fringe, AsXyz(mesh.nodes)));
      const double disc = M_PI * radius * radius;
      const double covered =
          TriangleAreas(flat, mesh.triangles) + TriangleAreas(flat, mesh.fringe.triangles);
      EXPECT_NEAR(covered, disc, 1e-3 * disc) << radius << " " << spacing;
      EXPECT_NEAR(covered, disc, 2e-5 * disc) << radius << " " << spacing;
      for (const Eigen::Vector3d& p : flat) {
        EXPECT_LE((p - spec.origin).norm(), radius * (1.0 + 1e-12));
        EXPECT_NEAR(p.z(), spec.origin.z(), 1e-15);
      }
      std::vector<Eigen::Vector3d> moved;
      for (const Eigen::Vector3d& p : mesh.nodes) moved.push_back(map * p + shift);
      const auto carried = AsPoints(WithFringePoints(mesh.fringe, AsXyz(moved)));
      for (size_t k = 0; k < carried.size(); ++k) {
        ASSERT_LT((carried[k] - (map * flat[k] + shift)).norm(), 1e-13) << k;
      }
    }
  }
}

TEST(Mesh, OnlyACircleHasAFringe) {
  EXPECT_TRUE(BuildMesh(GridSpec(4, 3, 1.0, 0.5)).fringe.points.empty());
  MeshSpec arc;
  arc.kind = MeshSpec::Kind::kArc;
  arc.radius = 0.2;
  arc.rings = 2;
  arc.spokes = 6;
  EXPECT_TRUE(BuildMesh(arc).fringe.triangles.empty());
}

TEST(Mesh, ArcHasRingsOnSpokesAndThePolygonArea) {
  MeshSpec spec;
  spec.kind = MeshSpec::Kind::kArc;
  spec.radius = 0.2;
  spec.rings = 3;
  spec.spokes = 8;
  const Mesh mesh = BuildMesh(spec);
  const int rings = spec.rings, spokes = spec.spokes;
  ASSERT_EQ(mesh.nodes.size(), static_cast<size_t>(1 + rings * spokes));
  EXPECT_EQ(mesh.nodes[0], spec.origin);
  for (int r = 1; r <= rings; ++r) {
    for (int k = 0; k < spokes; ++k) {
      EXPECT_NEAR(mesh.nodes[1 + (r - 1) * spokes + k].norm(), spec.radius * r / rings, 1e-15);
    }
  }
  EXPECT_EQ(mesh.warp.size(), static_cast<size_t>(rings * spokes));
  EXPECT_EQ(mesh.weft.size(), static_cast<size_t>(rings * spokes));
  EXPECT_EQ(mesh.shear.size(), static_cast<size_t>(2 * (rings - 1) * spokes));
  EXPECT_EQ(mesh.triangles.size(), static_cast<size_t>(spokes + 2 * (rings - 1) * spokes));
  // Skip-one along each spoke (from the centre) and across the centre, and around each ring.
  EXPECT_EQ(mesh.flexion_warp.size(), static_cast<size_t>((rings - 1) * spokes + spokes / 2));
  EXPECT_EQ(mesh.flexion_weft.size(), static_cast<size_t>(rings * spokes));
  const double polygon = spokes * 0.5 * spec.radius * spec.radius * std::sin(2 * M_PI / spokes);
  EXPECT_NEAR(Sum(mesh.area), polygon, 1e-14);
}

TEST(Mesh, ObjSquareOfTwoTriangles) {
  const Mesh mesh = BuildMesh(FileSpec("square.obj"));
  ASSERT_EQ(mesh.nodes.size(), 4u);
  EXPECT_EQ(mesh.triangles.size(), 2u);
  EXPECT_EQ(mesh.warp.size(), 5u);  // four sides and the shared diagonal
  ASSERT_EQ(mesh.flexion_warp.size(), 1u);
  EXPECT_EQ(mesh.flexion_warp[0], (Link{1, 3}));  // the vertices opposite the diagonal 0-2
  EXPECT_TRUE(mesh.weft.empty());
  EXPECT_TRUE(mesh.shear.empty());
  EXPECT_NEAR(Sum(mesh.area), 0.5 * 0.5, 1e-15);
  // A third of each triangle to each of its vertices: vertices 0 and 2 are in both.
  EXPECT_NEAR(mesh.area[0], 2 * (0.125 / 3), 1e-15);
  EXPECT_NEAR(mesh.area[1], 0.125 / 3, 1e-15);
}

TEST(Mesh, ObjQuadWithSlashIndicesAndPlyGiveTheSameSquare) {
  const Mesh triangles = BuildMesh(FileSpec("square.obj"));
  for (const char* name : {"square_quad.obj", "square.ply"}) {
    const Mesh mesh = BuildMesh(FileSpec(name));
    EXPECT_EQ(mesh.nodes, triangles.nodes) << name;
    EXPECT_EQ(mesh.triangles, triangles.triangles) << name;
    EXPECT_EQ(mesh.warp, triangles.warp) << name;
    EXPECT_EQ(mesh.flexion_warp, triangles.flexion_warp) << name;
  }
}

TEST(Mesh, ObjErrorsAreLocated) {
  const std::string bad_index = ErrorOf([] { BuildMesh(FileSpec("bad_index.obj")); });
  EXPECT_EQ(bad_index.rfind("scene.yaml:3:5: mesh: ", 0), 0u) << bad_index;
  EXPECT_NE(bad_index.find("bad_index.obj:7"), std::string::npos) << bad_index;
  EXPECT_NE(bad_index.find("vertex 5 is out of range"), std::string::npos) << bad_index;

  const std::string missing = ErrorOf([] { BuildMesh(FileSpec("no_such_file.obj")); });
  EXPECT_NE(missing.find("cannot read"), std::string::npos) << missing;
}

TEST(Mesh, CoincidentNodesAreNamed) {
  const std::string duplicate = ErrorOf([] { BuildMesh(FileSpec("duplicate_vertex.obj")); });
  EXPECT_NE(duplicate.find("nodes 2 and 4 coincide"), std::string::npos) << duplicate;

  MeshSpec chain;
  chain.kind = MeshSpec::Kind::kChain;
  chain.length = 0.0;
  chain.chain_nodes = 3;
  chain.where = SceneLocation();
  const std::string zero_length = ErrorOf([&] { BuildMesh(chain); });
  EXPECT_EQ(zero_length.rfind("scene.yaml:3:5: mesh: ", 0), 0u) << zero_length;
  EXPECT_NE(zero_length.find("coincide"), std::string::npos) << zero_length;
}

TEST(Mesh, FewerThanTwoNodesAreRejected) {
  const std::string message = ErrorOf([] { BuildMesh(GridSpec(1, 1, 1.0, 1.0)); });
  EXPECT_NE(message.find("at least 2"), std::string::npos) << message;
}

}  // namespace mesh_test
}  // namespace drape
