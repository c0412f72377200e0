// A closed, outward-oriented triangle surface: the boundary of a mesh obstacle's body
// (`obstacles: [{mesh: {file: form.obj}}]`), and the nearest-point query its contact term
// (costs/mesh_contact.h) and step limit need.
//
// Signed distance. The nearest point of the surface to x lies inside a face, on an edge or at a
// vertex. Its distance |x − p| is signed by the side of the surface x is on, read from the
// angle-weighted pseudo-normal of that feature (the face's normal; the sum of an edge's two face
// normals; the sum of a vertex's face normals weighted by their angles at it): for a closed,
// consistently oriented surface, x is outside exactly where (x − p) · n > 0 (Bærentzen & Aanæs,
// "Signed distance computation using the angle weighted pseudonormal", IEEE TVCG 11(3), 2005).
// The nearest point on one triangle is found by its Voronoi regions (Ericson, Real-Time Collision
// Detection, 2005, §5.1.5); the nearest triangle by branch and bound over a bounding-box tree
// (src/geometry/box_tree.h): O(log n) for a point near a surface of triangles of one size.
//
// Validity, checked when the surface is made (TriangleSurface::Make): at least 4 faces, no face of
// zero area, every edge shared by exactly two faces that run it in opposite directions (closed,
// manifold, consistently oriented: a hole, a non-manifold edge or one inverted face fails), and
// the enclosed volume positive (the normals point outward; a surface turned inside out fails).
#ifndef DRAPE_SRC_GEOMETRY_TRIANGLE_SURFACE_H_
#define DRAPE_SRC_GEOMETRY_TRIANGLE_SURFACE_H_

#include <Eigen/Core>
#include <array>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "src/geometry/box_tree.h"

namespace drape {

// Why a surface is not a closed, outward-oriented one: `face` is the first offending face's index
// in the faces given (-1: the whole surface).
class SurfaceError : public std::runtime_error {
 public:
  SurfaceError(int face_in, const std::string& what) : std::runtime_error(what), face(face_in) {}
  int face;
};

// The part of the surface nearest a point.
struct SurfaceFeature {
  // How many corners the feature has: 3 inside a face, 2 on an edge, 1 at a vertex.
  int corners = 0;
  std::array<Eigen::Vector3d, 3> corner;             // its corners (the first `corners`), m
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();  // unit normal of a face, else pseudo-normal
  Eigen::Vector3d point = Eigen::Vector3d::Zero();   // the nearest point, m
  double sign = 1.0;                                 // +1 outside the body, −1 inside
  double distance = 0.0;                             // signed distance |x − point| · sign, m
  int face = -1;                                     // a face the feature belongs to
};

class TriangleSurface {
 public:
  // Throws SurfaceError if the faces (vertex ids into `vertices`) are not a closed, outward-
  // oriented surface (see above).
  static std::shared_ptr<const TriangleSurface> Make(std::vector<Eigen::Vector3d> vertices,
                                                     std::vector<std::array<int, 3>> faces);

  // The nearest part of the surface to x (3 doubles). With `within`: only a part nearer than that
  // is looked for; if there is none, the feature has no corners and `distance` = within (|d| is at
  // least that; the side is not known). A bound near the surface makes the query far cheaper for
  // a point away from it (the tree's boxes farther than the bound are not opened).
  SurfaceFeature Nearest(const double* x,
                         double within = std::numeric_limits<double>::infinity()) const;
  // Its signed distance, m: positive outside the body.
  double SignedDistance(const double* x) const { return Nearest(x).distance; }

  // The faces whose boxes come within `margin` of `box`: every face nearer than `margin` to a
  // point of the box is among them.
  std::vector<int> FacesNear(const Box& box, double margin) const;
  // The (unsigned) distance from x to the nearest of `faces`, m; +∞ for none.
  double DistanceToFaces(const std::vector<int>& faces, const double* x) const;

  const std::vector<Eigen::Vector3d>& vertices() const { return vertices_; }
  const std::vector<std::array<int, 3>>& faces() const { return faces_; }
  const Eigen::Vector3d& face_normal(int face) const { return face_normals_[face]; }
  const Box& bounds() const { return tree_.bounds(); }
  double volume() const { return volume_; }  // m³

 private:
  TriangleSurface(std::vector<Eigen::Vector3d> vertices, std::vector<std::array<int, 3>> faces,
                  std::vector<Box> boxes);
  void CheckClosedAndOriented() const;
  void ComputePseudoNormals();

  std::vector<Eigen::Vector3d> vertices_;
  std::vector<std::array<int, 3>> faces_;
  std::vector<Eigen::Vector3d> face_normals_;
  std::vector<std::array<Eigen::Vector3d, 3>> edge_normals_;  // edge k: corners k and k+1
  std::vector<Eigen::Vector3d> vertex_normals_;
  BoxTree tree_;
  double volume_ = 0.0;
};

// A mesh file's vertex placed in the scene: x' = R (s x) + t, R = Rz(rz) Ry(ry) Rx(rx) for
// `rotation_degrees` = (rx, ry, rz): rotations about the fixed axes x, then y, then z.
Eigen::Vector3d PlaceVertex(const Eigen::Vector3d& vertex, double scale,
                            const Eigen::Vector3d& rotation_degrees,
                            const Eigen::Vector3d& translation);

}  // namespace drape

#endif  // DRAPE_SRC_GEOMETRY_TRIANGLE_SURFACE_H_
