#include "src/model/obstacle_kinds.h"

#include <algorithm>
#include <cassert>
#include <limits>

#include "costs/box_contact.h"
#include "costs/cylinder_contact.h"
#include "costs/disk_contact.h"
#include "costs/edge_contact.h"
#include "costs/mesh_contact.h"
#include "costs/plane_contact.h"
#include "costs/sphere_contact.h"

namespace drape {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// A row whose distance and contact terms come from the functor `make(obstacle, t, k)` returns
// (the terms are named "<kind>_contact" for a node, "<kind>_edge_contact" for an edge's inside).
template <typename MakeFunctor>
ObstacleKind Row(const std::string& name, std::vector<std::string> keys, std::string doc,
                 bool support, MakeFunctor make) {
  ObstacleKind kind;
  kind.name = name;
  kind.keys = std::move(keys);
  kind.doc = std::move(doc);
  kind.support = support;
  kind.distance = [make](const ObstacleSpec& obstacle, const double* x) {
    return make(obstacle, 0.0, 0.0).Distance(x);
  };
  kind.make_term = [make, type = name + "_contact"](const ObstacleSpec& obstacle, int node,
                                                    double clearance, double stiffness,
                                                    double shift) {
    return MakeTerm(type, {node}, make(obstacle, clearance, stiffness), shift);
  };
  kind.make_edge_term = [make, type = name + "_edge_contact"](const ObstacleSpec& obstacle, int a,
                                                              int b, int points, double clearance,
                                                              double stiffness, double shift) {
    return MakeTerm(type, {a, b}, EdgeContact(make(obstacle, clearance, stiffness), points), shift);
  };
  kind.check = [](const ObstacleSpec&) {};
  return kind;
}

ObstaclePart Sphere(const Eigen::Vector3d& centre, double radius) {
  ObstaclePart part;
  part.shape = ObstaclePart::Shape::kSphere;
  part.a = centre;
  part.radius = radius;
  return part;
}

ObstaclePart Cylinder(const Eigen::Vector3d& top_centre, double radius, double height,
                      bool capped) {
  ObstaclePart part;
  part.shape = ObstaclePart::Shape::kCylinder;
  part.a = top_centre;
  part.radius = radius;
  part.height = height;
  part.capped = capped;
  return part;
}

ObstacleKind SphereRow() {
  ObstacleKind row = Row("sphere", {"center", "radius"}, "`center` [3], `radius` > 0", false,
                         [](const ObstacleSpec& o, double t, double k) {
                           return SphereContact::Create(o.center.data(), o.radius, t, k);
                         });
  row.draw = [](const ObstacleSpec& o, const DrawingFrame&) -> std::vector<ObstaclePart> {
    return {Sphere(o.center, o.radius)};
  };
  row.lowest_z = [](const ObstacleSpec& o) { return o.center.z() - o.radius; };
  return row;
}

// A drape tester's pedestal top, drawn on a stem (a tenth of its radius) down to the floor.
ObstacleKind DiskRow() {
  ObstacleKind row = Row("disk", {"center", "radius"},
                         "`center` [3], `radius` > 0 — a pedestal top, as in a drape tester", true,
                         [](const ObstacleSpec& o, double t, double k) {
                           return DiskContact::Create(o.center.data(), o.radius, t, k);
                         });
  row.draw = [](const ObstacleSpec& o, const DrawingFrame& frame) -> std::vector<ObstaclePart> {
    const double stem = std::max(o.center.z() - frame.floor_z, 0.02 * o.radius);
    return {Cylinder(o.center, o.radius, 0.02 * o.radius, true),
            Cylinder(o.center, 0.1 * o.radius, stem, false)};
  };
  row.lowest_z = [](const ObstacleSpec&) { return kInfinity; };
  return row;
}

ObstacleKind CylinderRow() {
  ObstacleKind row =
      Row("cylinder", {"center", "radius", "height"},
          "`center` [3] (the centre of its top face), `radius` > 0, `height` > 0 "
          "(it extends downward, like a pedestal)",
          false, [](const ObstacleSpec& o, double t, double k) {
            return CylinderContact::Create(o.center.data(), o.radius, o.height, t, k);
          });
  row.draw = [](const ObstacleSpec& o, const DrawingFrame&) -> std::vector<ObstaclePart> {
    return {Cylinder(o.center, o.radius, o.height, true)};
  };
  row.lowest_z = [](const ObstacleSpec& o) { return o.center.z() - o.height; };
  return row;
}

ObstacleKind BoxRow() {
  ObstacleKind row = Row("box", {"min", "max"}, "`min` [3], `max` [3] (max > min)", false,
                         [](const ObstacleSpec& o, double t, double k) {
                           return BoxContact::Create(o.min.data(), o.max.data(), t, k);
                         });
  row.draw = [](const ObstacleSpec& o, const DrawingFrame&) {
    ObstaclePart part;
    part.shape = ObstaclePart::Shape::kBox;
    part.a = o.min;
    part.b = o.max;
    return std::vector<ObstaclePart>{part};
  };
  row.lowest_z = [](const ObstacleSpec& o) { return o.min.z(); };
  row.check = [](const ObstacleSpec& o) {
    if (!(o.min.array() < o.max.array()).all()) {
      throw InputError(o.given.at("max"), "max must exceed min in every coordinate");
    }
  };
  return row;
}

// The scene gives the plane's `point` in ObstacleSpec::center.
ObstacleKind PlaneRow() {
  ObstacleKind row =
      Row("plane", {"point", "normal"}, "`point` [3], `normal` [3] (not zero; normalised)", false,
          [](const ObstacleSpec& o, double t, double k) {
            return PlaneContact::Create(o.center.data(), o.normal.data(), t, k);
          });
  row.draw = [](const ObstacleSpec& o, const DrawingFrame&) {
    ObstaclePart part;
    part.shape = ObstaclePart::Shape::kPlane;
    part.a = o.center;
    part.b = o.normal.normalized();
    return std::vector<ObstaclePart>{part};
  };
  row.lowest_z = [](const ObstacleSpec&) { return -kInfinity; };
  row.make_edge_term = nullptr;  // an edge between two points outside a half-space stays outside
  return row;
}

// A point support: a sphere of radius 0 around its tip (costs/sphere_contact.h), drawn as a thin
// stem down to the floor. The scene gives its `position` in ObstacleSpec::center.
ObstacleKind PinRow() {
  ObstacleKind row = Row("pin", {"position"}, "`position` [3]", true,
                         [](const ObstacleSpec& o, double t, double k) {
                           return SphereContact::Create(o.center.data(), 0.0, t, k);
                         });
  row.draw = [](const ObstacleSpec& o, const DrawingFrame& frame) -> std::vector<ObstaclePart> {
    const double stem = std::max(o.center.z() - frame.floor_z, 0.05 * frame.extent);
    return {Cylinder(o.center, 0.006 * frame.extent, stem, true)};
  };
  row.lowest_z = [](const ObstacleSpec&) { return kInfinity; };
  // A point passes through a triangle's inside as easily as through an edge, which no edge term
  // prevents: the fabric rests on a pin at a node (a scene puts one over it).
  row.make_edge_term = nullptr;
  return row;
}

// A rigid body bounded by a closed triangle surface read from a file (src/scene/obstacle_mesh.h).
ObstacleKind MeshRow() {
  ObstacleKind row =
      Row("mesh", {"file"},
          "`file` (OBJ, PLY or STL: a closed surface, outward normals), `scale` > 0, `rotation` "
          "[3] (degrees), `translation` [3]",
          false, [](const ObstacleSpec& o, double t, double k) {
            assert(o.surface != nullptr && "the scene loader reads a mesh obstacle's file");
            return MeshContact<TriangleSurface>(o.surface, t, k);
          });
  // The exact distance everywhere (the functor's looks no farther than 2t).
  row.distance = [](const ObstacleSpec& o, const double* x) {
    return o.surface->SignedDistance(x);
  };
  row.bounded_distance = [](const ObstacleSpec& o, const double* x, double within) {
    return o.surface->Nearest(x, within).distance;
  };
  row.optional_keys = {"scale", "rotation", "translation"};
  row.convex = false;
  row.draw = [](const ObstacleSpec& o, const DrawingFrame&) {
    ObstaclePart part;
    part.shape = ObstaclePart::Shape::kSurface;
    part.surface = o.surface;
    return std::vector<ObstaclePart>{part};
  };
  row.lowest_z = [](const ObstacleSpec& o) { return o.surface->bounds().low.z(); };
  return row;
}

bool Contains(const std::vector<std::string>& keys, const std::string& key) {
  return std::find(keys.begin(), keys.end(), key) != keys.end();
}

std::string KindNames() {
  std::string names;
  for (const ObstacleKind& kind : ObstacleKinds()) names += (names.empty() ? "" : ", ") + kind.name;
  return names;
}

const ObstacleKind* FindKind(const std::string& name) {
  for (const ObstacleKind& kind : ObstacleKinds()) {
    if (kind.name == name) return &kind;
  }
  return nullptr;
}

}  // namespace

const std::vector<ObstacleKind>& ObstacleKinds() {
  static const std::vector<ObstacleKind> kinds = {SphereRow(), DiskRow(), CylinderRow(), BoxRow(),
                                                  PlaneRow(),  PinRow(),  MeshRow()};
  return kinds;
}

const ObstacleKind& CheckedObstacleKind(const ObstacleSpec& obstacle) {
  const ObstacleKind* kind = FindKind(obstacle.kind);
  if (kind == nullptr) {
    throw InputError(obstacle.where, "unknown obstacle '" + obstacle.kind +
                                         "' (expected one of: " + KindNames() + ")");
  }
  for (const auto& [key, where] : obstacle.given) {
    if (key != "friction" && !Contains(kind->keys, key) && !Contains(kind->optional_keys, key)) {
      std::string keys;
      for (const std::string& name : kind->keys) keys += name + ", ";
      for (const std::string& name : kind->optional_keys) keys += name + ", ";
      throw InputError(
          where, "a " + kind->name + " takes no '" + key + "' (its keys: " + keys + "friction)");
    }
  }
  for (const std::string& key : kind->keys) {
    if (obstacle.given.count(key) == 0) {
      Location where = obstacle.where;
      where.key += "." + key;
      throw InputError(where, "required key '" + key + "' is missing");
    }
  }
  kind->check(obstacle);
  return *kind;
}

const ObstacleKind& ObstacleKindOf(const ObstacleSpec& obstacle) {
  const ObstacleKind* kind = FindKind(obstacle.kind);
  assert(kind != nullptr && "an obstacle kind the model build did not check");
  return *kind;
}

}  // namespace drape
