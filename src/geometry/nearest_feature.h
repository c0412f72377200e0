// Which part of a triangle is nearest a point, and which parts of two segments are nearest each
// other: the classification that a contact's distance is written on (costs/self_contact.h,
// costs/edge_edge_contact.h) and a mesh obstacle's nearest-point query (src/geometry/
// triangle_surface.h) uses. Deciding the part is the only place a minimum is taken; the distance
// to the part chosen is then a smooth function of the positions (to a plane, a line or a point),
// which automatic differentiation can go through, as IPC's distance types are (Li et al. 2020,
// "Incremental Potential Contact", ACM Trans. Graph. 39(4), §4.2). The regions: Ericson,
// Real-Time Collision Detection (2005), §5.1.5 (point–triangle, by Voronoi regions) and §5.1.9
// (segment–segment).
#ifndef DRAPE_SRC_GEOMETRY_NEAREST_FEATURE_H_
#define DRAPE_SRC_GEOMETRY_NEAREST_FEATURE_H_

#include <Eigen/Core>
#include <array>

namespace drape {

// The point of triangle a b c nearest p, and the part it lies on: `corners` 3 (the inside), 2
// (the side from corner `first` to corner (first + 1) mod 3) or 1 (corner `first`); corners are
// numbered 0 (a), 1 (b), 2 (c). A triangle of zero area has no inside: its nearest side is taken.
struct TrianglePoint {
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
  int corners = 3;
  int first = 0;
};
TrianglePoint NearestOnTriangle(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                                const Eigen::Vector3d& b, const Eigen::Vector3d& c);

// The distance from p to the triangle a b c, m.
double PointTriangleDistance(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                             const Eigen::Vector3d& b, const Eigen::Vector3d& c);

// The parts of the segments a–b and c–d nearest each other. Ends are numbered 0 (a), 1 (b), 2 (c),
// 3 (d). kInsides: a point inside each (the distance is that of their two lines); kEndToInside:
// end `end` and the inside of the other segment (ends `other`, `other` + 1); kEnds: end `end` and
// end `other`. Parallel segments (no single pair of inside points is nearest) are taken end to
// inside or end to end.
struct SegmentPairFeature {
  enum Kind { kInsides, kEndToInside, kEnds };
  Kind kind = kInsides;
  int end = -1;
  int other = -1;
};
SegmentPairFeature NearestSegmentFeatures(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                          const Eigen::Vector3d& c, const Eigen::Vector3d& d);

// The distance between the segments a–b and c–d, m.
double SegmentSegmentDistance(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                              const Eigen::Vector3d& c, const Eigen::Vector3d& d);

}  // namespace drape

#endif  // DRAPE_SRC_GEOMETRY_NEAREST_FEATURE_H_
