// The obstacle kinds: one row each, the single owner of everything drape knows about a kind (its
// name in the scene file, its keys, its contact functor in costs/, how it is drawn, whether it is
// a drape tester's support). The scene loader reads an obstacle's keys (each key's range is the
// loader's); which kind takes which keys is checked here, when the model is built.
//
// Adding a kind: costs/<kind>_contact.h (the functor, with its signed Distance), one row in
// ObstacleKinds() (src/model/obstacle_kinds.cc), its tests (tests/<kind>_contact_test.cc), and its
// line in docs/reference.md's obstacle table (tests/obstacle_kinds_test.cc checks the table against
// the rows). A key no kind had before also needs its reading in src/scene/scene_loader.cc
// (ReadObstacleKey).
#ifndef DRAPE_SRC_MODEL_OBSTACLE_KINDS_H_
#define DRAPE_SRC_MODEL_OBSTACLE_KINDS_H_

#include <Eigen/Core>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "src/geometry/triangle_surface.h"
#include "src/model/term.h"
#include "src/scene/scene.h"

namespace drape {

// A solid the picture (src/output/render.cc) draws for an obstacle.
struct ObstaclePart {
  enum class Shape {
    kSphere,    // centre `a`, `radius`
    kCylinder,  // vertical, top centre `a`, `radius`, `height` downward, `capped` top
    kBox,       // corners `a` (min) and `b` (max)
    kPlane,     // point `a`, unit normal `b`: a patch around the fabric
    kSurface,   // the triangles of `surface`
  };
  Shape shape = Shape::kSphere;
  Eigen::Vector3d a = Eigen::Vector3d::Zero(), b = Eigen::Vector3d::Zero();
  double radius = 0.0, height = 0.0;
  bool capped = true;
  std::shared_ptr<const TriangleSurface> surface;
};

// What the picture knows of the scene when it draws an obstacle.
struct DrawingFrame {
  double extent = 1.0;   // the fabric's largest extent, m
  double floor_z = 0.0;  // height of the floor drawn under the fabric, m
};

struct ObstacleKind {
  std::string name;                        // the key in the scene file: "sphere"
  std::vector<std::string> keys;           // all required; `friction` is accepted by every kind
  std::vector<std::string> optional_keys;  // keys with a default
  std::string doc;                         // docs/reference.md's obstacle table: the keys' meaning
  // A drape tester's support (disk, pin): the drape profile is centred on it, and its radius is
  // the Cusick coefficient's disc radius.
  bool support = false;
  // Whether the body is convex: the distance along a straight move is then convex, which the step
  // limit's search uses (src/model/contact.h, ObstacleSafeFraction).
  bool convex = true;
  // Signed distance from x (3 doubles) to the surface, m, positive outside.
  std::function<double(const ObstacleSpec&, const double* x)> distance;
  // The same where its magnitude is below `within`, else `within` (a point that far on either
  // side); null where `distance` is as cheap.
  std::function<double(const ObstacleSpec&, const double* x, double within)> bounded_distance;
  // The contact term of `node` (costs/contact_penalty.h: clearance t, stiffness k, the least-
  // squares shift of src/model/term.h).
  std::function<std::unique_ptr<Term>(const ObstacleSpec&, int node, double clearance,
                                      double stiffness, double shift)>
      make_term;
  // The contact term of the inside of the fabric edge a–b, at `points` points along it
  // (costs/edge_contact.h); null for the plane (a straight edge between two nodes outside a
  // half-space stays outside) and the pin (a point: see PinRow).
  std::function<std::unique_ptr<Term>(const ObstacleSpec&, int a, int b, int points,
                                      double clearance, double stiffness, double shift)>
      make_edge_term;
  // The solids that draw it.
  std::function<std::vector<ObstaclePart>(const ObstacleSpec&, const DrawingFrame&)> draw;
  // The height of its lowest point, m (+∞ for a body drawn down to the floor, −∞ for an
  // unbounded one).
  std::function<double(const ObstacleSpec&)> lowest_z;
  // Checks between keys beyond each key's own range (box: max > min); throws InputError.
  std::function<void(const ObstacleSpec&)> check;
};

// Every kind, in the order of the reference's table.
const std::vector<ObstacleKind>& ObstacleKinds();

// The row of `obstacle.kind`; throws InputError at the obstacle for an unknown kind, a missing
// key or a key its kind does not take.
const ObstacleKind& CheckedObstacleKind(const ObstacleSpec& obstacle);

// The row of a kind already checked (an assertion otherwise).
const ObstacleKind& ObstacleKindOf(const ObstacleSpec& obstacle);

}  // namespace drape

#endif  // DRAPE_SRC_MODEL_OBSTACLE_KINDS_H_
