#include "src/geometry/triangle_surface.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <sstream>
#include <utility>

#include "src/geometry/nearest_feature.h"

namespace drape {

namespace {

using Eigen::Vector3d;

std::vector<Box> FaceBoxes(const std::vector<Vector3d>& vertices,
                           const std::vector<std::array<int, 3>>& faces) {
  std::vector<Box> boxes(faces.size());
  for (size_t f = 0; f < faces.size(); ++f) {
    for (int corner : faces[f]) boxes[f].Add(vertices[corner]);
  }
  return boxes;
}

std::string FaceText(int face) { return "face " + std::to_string(face + 1); }

}  // namespace

std::shared_ptr<const TriangleSurface> TriangleSurface::Make(
    std::vector<Vector3d> vertices, std::vector<std::array<int, 3>> faces) {
  if (faces.size() < 4) {
    throw SurfaceError(-1, "a closed surface needs at least 4 triangles, this one has " +
                               std::to_string(faces.size()));
  }
  for (size_t f = 0; f < faces.size(); ++f) {
    for (int corner : faces[f]) {
      if (corner < 0 || corner >= static_cast<int>(vertices.size())) {
        throw SurfaceError(static_cast<int>(f), FaceText(static_cast<int>(f)) + " names vertex " +
                                                    std::to_string(corner + 1) + " of " +
                                                    std::to_string(vertices.size()));
      }
    }
  }
  std::vector<Box> boxes = FaceBoxes(vertices, faces);
  std::shared_ptr<TriangleSurface> surface(
      new TriangleSurface(std::move(vertices), std::move(faces), std::move(boxes)));
  surface->CheckClosedAndOriented();
  surface->ComputePseudoNormals();
  return surface;
}

TriangleSurface::TriangleSurface(std::vector<Vector3d> vertices,
                                 std::vector<std::array<int, 3>> faces, std::vector<Box> boxes)
    : vertices_(std::move(vertices)), faces_(std::move(faces)), tree_(std::move(boxes)) {
  face_normals_.resize(faces_.size());
  for (size_t f = 0; f < faces_.size(); ++f) {
    const Vector3d& a = vertices_[faces_[f][0]];
    const Vector3d normal = (vertices_[faces_[f][1]] - a).cross(vertices_[faces_[f][2]] - a);
    const double twice_area = normal.norm();
    if (!(twice_area > 0.0)) {
      throw SurfaceError(static_cast<int>(f), FaceText(static_cast<int>(f)) +
                                                  " has zero area (its corners are in a line)");
    }
    face_normals_[f] = normal / twice_area;
    volume_ += a.dot(normal) / 6.0;
  }
}

void TriangleSurface::CheckClosedAndOriented() const {
  // Each directed edge (from, to) once; then each must have its reverse.
  std::map<std::pair<int, int>, int> directed;
  for (size_t f = 0; f < faces_.size(); ++f) {
    for (int k = 0; k < 3; ++k) {
      const std::pair<int, int> edge = {faces_[f][k], faces_[f][(k + 1) % 3]};
      const auto [at, inserted] = directed.insert({edge, static_cast<int>(f)});
      if (!inserted) {
        std::ostringstream text;
        text << FaceText(static_cast<int>(f)) << " runs the edge from vertex " << edge.first + 1
             << " to vertex " << edge.second + 1 << " the same way as " << FaceText(at->second)
             << ": a face turned over (the faces' vertex orders must agree) or an edge shared by "
                "more than two faces";
        throw SurfaceError(static_cast<int>(f), text.str());
      }
    }
  }
  for (const auto& [edge, face] : directed) {
    if (directed.count({edge.second, edge.first}) == 0) {
      std::ostringstream text;
      text << "the surface has a hole: the edge from vertex " << edge.first + 1 << " to vertex "
           << edge.second + 1 << " of " << FaceText(face)
           << " has no face on its other side (an obstacle must be a closed surface)";
      throw SurfaceError(face, text.str());
    }
  }
  if (!(volume_ > 0.0)) {
    std::ostringstream text;
    text << "the surface is inside out (it encloses a volume of " << volume_
         << " m³): its faces' normals point inward; reverse their vertex order";
    throw SurfaceError(-1, text.str());
  }
}

void TriangleSurface::ComputePseudoNormals() {
  std::map<std::pair<int, int>, Vector3d> edge_sum;
  vertex_normals_.assign(vertices_.size(), Vector3d::Zero());
  for (size_t f = 0; f < faces_.size(); ++f) {
    for (int k = 0; k < 3; ++k) {
      const int from = faces_[f][k], to = faces_[f][(k + 1) % 3], before = faces_[f][(k + 2) % 3];
      const auto key = std::minmax(from, to);
      // (Eigen's vectors are not zeroed when made: the sum starts from an explicit zero.)
      edge_sum.try_emplace({key.first, key.second}, Vector3d::Zero()).first->second +=
          face_normals_[f];
      const Vector3d u = (vertices_[to] - vertices_[from]).normalized();
      const Vector3d v = (vertices_[before] - vertices_[from]).normalized();
      const double angle = std::atan2(u.cross(v).norm(), u.dot(v));
      vertex_normals_[from] += angle * face_normals_[f];
    }
  }
  edge_normals_.resize(faces_.size());
  for (size_t f = 0; f < faces_.size(); ++f) {
    for (int k = 0; k < 3; ++k) {
      const auto key = std::minmax(faces_[f][k], faces_[f][(k + 1) % 3]);
      edge_normals_[f][k] = edge_sum.at({key.first, key.second});
    }
  }
}

SurfaceFeature TriangleSurface::Nearest(const double* x, double within) const {
  const Vector3d p(x[0], x[1], x[2]);
  TrianglePoint found;
  double found_squared = std::numeric_limits<double>::infinity(), best;
  const int face = tree_.Nearest(
      p, within * within,
      [&](int f) {
        const TrianglePoint candidate = NearestOnTriangle(
            p, vertices_[faces_[f][0]], vertices_[faces_[f][1]], vertices_[faces_[f][2]]);
        const double squared = (p - candidate.point).squaredNorm();
        if (squared < found_squared) found = candidate, found_squared = squared;
        return squared;
      },
      &best);
  SurfaceFeature feature;
  if (face < 0) {  // nothing within the bound, or a point not finite
    feature.distance = p.allFinite() ? within : std::numeric_limits<double>::quiet_NaN();
    return feature;
  }
  feature.face = face;
  feature.corners = found.corners;
  for (int k = 0; k < found.corners; ++k) {
    feature.corner[k] = vertices_[faces_[face][(found.first + k) % 3]];
  }
  feature.normal = found.corners == 3   ? face_normals_[face]
                   : found.corners == 2 ? edge_normals_[face][found.first]
                                        : vertex_normals_[faces_[face][found.first]];
  feature.point = found.point;
  const Vector3d offset = p - found.point;
  feature.sign = offset.dot(feature.normal) >= 0.0 ? 1.0 : -1.0;
  feature.distance = feature.sign * offset.norm();
  return feature;
}

std::vector<int> TriangleSurface::FacesNear(const Box& box, double margin) const {
  Box query = box;
  query.low.array() -= margin;
  query.high.array() += margin;
  std::vector<int> faces;
  tree_.ForEachOverlap(query, [&faces](int face) { faces.push_back(face); });
  return faces;
}

double TriangleSurface::DistanceToFaces(const std::vector<int>& faces, const double* x) const {
  const Vector3d p(x[0], x[1], x[2]);
  double best = std::numeric_limits<double>::infinity();
  for (int f : faces) {
    const TrianglePoint nearest = NearestOnTriangle(
        p, vertices_[faces_[f][0]], vertices_[faces_[f][1]], vertices_[faces_[f][2]]);
    best = std::min(best, (p - nearest.point).squaredNorm());
  }
  return std::sqrt(best);
}

Vector3d PlaceVertex(const Vector3d& vertex, double scale, const Vector3d& rotation_degrees,
                     const Vector3d& translation) {
  const Vector3d r = rotation_degrees * (M_PI / 180.0);
  const Eigen::Matrix3d rotation =
      (Eigen::AngleAxisd(r.z(), Vector3d::UnitZ()) * Eigen::AngleAxisd(r.y(), Vector3d::UnitY()) *
       Eigen::AngleAxisd(r.x(), Vector3d::UnitX()))
          .toRotationMatrix();
  return rotation * (scale * vertex) + translation;
}

}  // namespace drape
