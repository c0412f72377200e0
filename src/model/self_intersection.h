// Where the fabric passes through itself: the certificate's check that no piece of the fabric's
// surface crosses another.
//
// Two triangles of a surface that pass through each other cross along a segment; each end of that
// segment is where a side of one of them crosses the other. So a triangulated surface passes
// through itself exactly where a side of one triangle crosses a triangle that shares no node with
// it, and the count of such (side, triangle) pairs is zero for a surface that does not (IPC's
// definition of an intersection-free state: Li et al. 2020, "Incremental Potential Contact",
// ACM Trans. Graph. 39(4), §4). Triangles that share a node meet there by construction and are
// not tested against each other.
//
// A crossing is decided by the signs of triple products (orientations): the side's ends lie
// strictly on opposite sides of the triangle's plane, and the side passes strictly inside the
// triangle's three edges. A triple product within kCrossingTolerance of the product of its three
// vectors' lengths counts as zero, so a side that only touches a triangle, lies in its plane, or
// crosses it at an angle below about 1e-12 rad is not counted: rounding makes the sign of such a
// product meaningless (a flat sheet tilted out of a coordinate plane has all its triple products
// of that size), and a crossing that shallow is a touch, not a passage.
//
// The candidates come from a bounding-box tree over the triangles (built afresh at each call,
// O(n log n)), queried with each side's box: the cost is near-linear in the triangles for a
// fabric whose triangles are of one size.
#ifndef DRAPE_SRC_MODEL_SELF_INTERSECTION_H_
#define DRAPE_SRC_MODEL_SELF_INTERSECTION_H_

#include <Eigen/Core>
#include <array>
#include <vector>

#include "src/model/model.h"

namespace drape {

constexpr double kCrossingTolerance = 1e-12;  // of |u| |v| |w| for the triple product u · (v × w)

struct SelfIntersections {
  // False where the positions were not all finite (nothing was tested: a state that is not finite
  // is not certified anyway).
  bool checked = false;
  int triangles = 0;  // triangles tested (the fabric's surface, Model::triangles)
  int crossings = 0;  // (side, triangle) pairs that cross
  // The first crossing found in node order (the side's lower node, then its higher, then the
  // triangle's index), to name in a message: the side's nodes and the triangle's.
  std::array<int, 2> side = {-1, -1};
  std::array<int, 3> triangle = {-1, -1, -1};
  bool Any() const { return crossings > 0; }
};

// Every side of the triangles once, as (lower, higher) node ids, in increasing order.
std::vector<std::array<int, 2>> SidesOf(const std::vector<std::array<int, 3>>& triangles);

// Whether the segment p–q crosses the triangle a b c (see above).
bool SegmentCrossesTriangle(const Eigen::Vector3d& p, const Eigen::Vector3d& q,
                            const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                            const Eigen::Vector3d& c);

// The crossings of `triangles` (node ids into `positions`, 3 doubles per node) with their own
// sides.
SelfIntersections FindSelfIntersections(const std::vector<std::array<int, 3>>& triangles,
                                        const std::vector<double>& positions);

// The same for the model's fabric (Model::triangles) at `positions` (3 per node). The fringe of a
// circle mesh (Model::fringe: points interpolated from the nodes beyond the lattice, drawn in the
// shadow but carrying no energy) is not tested: it follows the nodes, and nothing in the model
// keeps it from crossing them.
SelfIntersections FindSelfIntersections(const Model& model, const std::vector<double>& positions);

}  // namespace drape

#endif  // DRAPE_SRC_MODEL_SELF_INTERSECTION_H_
