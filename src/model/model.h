// The model: nodes, their rest state, which coordinates are fixed, and the energy terms the scene
// needs (and no others). Built from a Scene by BuildModel(); validated before any ceres::Problem
// is made from it (Ceres aborts on misuse).
#ifndef DRAPE_SRC_MODEL_MODEL_H_
#define DRAPE_SRC_MODEL_MODEL_H_

#include <Eigen/Core>
#include <array>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "src/model/mesh.h"
#include "src/model/term.h"
#include "src/scene/scene.h"

namespace drape {

// One node's 3 coordinates in an array of 3 per node (positions, forces, loads): NodeAt(x, k) in
// place of x[3 * k + c].
inline Eigen::Map<Eigen::Vector3d> NodeAt(double* values, int node) {
  return Eigen::Map<Eigen::Vector3d>(values + 3 * node);
}
inline Eigen::Map<const Eigen::Vector3d> NodeAt(const double* values, int node) {
  return Eigen::Map<const Eigen::Vector3d>(values + 3 * node);
}
inline Eigen::Map<Eigen::Vector3d> NodeAt(std::vector<double>& values, int node) {
  return NodeAt(values.data(), node);
}
inline Eigen::Map<const Eigen::Vector3d> NodeAt(const std::vector<double>& values, int node) {
  return NodeAt(values.data(), node);
}

struct Model {
  int dimension = 3;
  int num_nodes = 0;
  // Positions, 3 doubles per node. `positions` is the storage the solvers move and Ceres'
  // parameter blocks point into: it is sized once by BuildModel and never reallocated.
  std::vector<double> positions;
  std::vector<double> initial;                 // the start, after `move` of fixed nodes, 3 per node
  std::vector<double> mass;                    // kg per node (lumped)
  std::vector<char> fixed;                     // 3 per node: 1 where that coordinate is prescribed
  std::vector<std::array<int, 2>> grid_index;  // (i, j) of grid nodes, (-1, -1) otherwise
  std::vector<std::array<int, 3>> triangles;   // surface faces for mesh.vtk / mesh.obj
  std::vector<std::array<int, 2>> edges;       // line elements (chains) for mesh.vtk / mesh.obj
  Fringe fringe;                // the specimen beyond `triangles` (circle meshes; src/model/mesh.h)
  std::vector<double> applied;  // 3 per node: weight + applied loads, N (constant)
  std::vector<std::unique_ptr<Term>> terms;
  double size = 1.0;  // diameter of the initial shape, m (for relative distances)
  // material.springs.stretch_limit (maximum stretch ratio), 0 when the scene sets none; the
  // explicit-euler solver enforces it with Provot's constraint (src/model/stretch_limit.h).
  double stretch_limit = 0.0;
  // The scene's obstacles and contact settings (src/model/contact.h), and every contact term: for
  // the step limit, the contact forces and the certificate.
  std::vector<ObstacleSpec> obstacles;
  ContactSpec contact;
  struct ContactTerm {
    int term = 0;           // its index in `terms`
    int obstacle = 0;       // its obstacle's index in `obstacles`
    int edge_points = 0;    // 0: a node's term; else an edge's, at that many points inside it
    bool friction = false;  // the obstacle's friction on a node (costs/obstacle_friction.h)
  };
  std::vector<ContactTerm> contact_terms;
  // The obstacles' pushes the friction terms were made with (src/model/contact.h,
  // AddObstacleFrictionTerms): the lagged normal forces, one per obstacle with a friction and node
  // it pushed on.
  struct Push {
    int obstacle = 0;
    int node = 0;
    Eigen::Vector3d force = Eigen::Vector3d::Zero();  // N
  };
  std::vector<Push> friction_pushes;
  // The fabric's contact with itself (src/model/self_contact.h): its pairs' terms are
  // terms[self_contact.first_term ..), the last of `terms`, and change as the fabric moves.
  struct SelfContact {
    bool enabled = false;
    double clearance = 0.0;  // C, m: the fabric's thickness, 2 × contact.thickness
    double stiffness = 0.0;  // k, N/m²
    int first_term = 0;      // the first self-contact term in `terms`
    int generation = 0;      // how many times its terms were replaced (a Hessian pattern's stamp)
    std::vector<std::array<int, 2>> sides;  // the fabric's triangle sides, each once
    // The rest-shape neighbours, which never have a term: for each node the triangles, for each
    // side the sides of higher index, nearer than kSelfRestFactor × C in `initial` (sorted, in
    // compressed rows: those of k are items[start[k] .. start[k + 1])).
    std::vector<int> neighbour_triangle_start, neighbour_triangles;
    std::vector<int> neighbour_side_start, neighbour_sides;
    bool neighbours_found = false;  // the lists above are made (at the first UpdateSelfContact)
    // The pairs that have terms: (node, triangle index) and (side index, side index), sorted.
    std::vector<std::array<int, 2>> point_triangle, edge_edge;
    std::vector<double> built_at;  // the positions the pairs were found at (3 per node)
  };
  SelfContact self_contact;
  // For each region of the scene (regions:), how many nodes it selects and how many of those no
  // later region selects too (for drape check).
  struct RegionCount {
    int selected = 0;
    int last = 0;
  };
  std::vector<RegionCount> region_counts;

  int num_dofs() const { return 3 * num_nodes; }
  // Node views: one node's coordinates of `positions`, `initial`, `applied`.
  Eigen::Map<Eigen::Vector3d> position(int node) { return NodeAt(positions, node); }
  Eigen::Map<const Eigen::Vector3d> position(int node) const { return NodeAt(positions, node); }
  Eigen::Map<const Eigen::Vector3d> initial_position(int node) const {
    return NodeAt(initial, node);
  }
  Eigen::Map<const Eigen::Vector3d> applied_force(int node) const { return NodeAt(applied, node); }
  // Whether all three coordinates of `node` are prescribed.
  bool fully_fixed(int node) const {
    return fixed[3 * node] && fixed[3 * node + 1] && fixed[3 * node + 2];
  }
  int num_free_dofs() const;
  // Number of terms of each type, for summary.json.
  std::map<std::string, int> TermCounts() const;
};

// Builds the model of a loaded scene. Throws InputError (located at the offending key) for what
// only shows at this stage: empty selections, ids out of range, coincident nodes, a mesh with fewer
// than 2 nodes, an unreadable mesh file, an energy with no minimum.
// `friction_reference`, when given (the positions of every node, 3 per node), puts the frictions'
// kinks there instead of at the flat state: a later load step of the incremental form
// (FiniteVolumeSpec::friction_load_steps). `pushed_at`, when given (3 per node), is where the
// obstacles' friction takes its normal forces (the lagged state: src/model/contact.h,
// AddObstacleFrictionTerms); null: the start.
Model BuildModel(const Scene& scene, const std::vector<double>* friction_reference = nullptr,
                 const std::vector<double>* pushed_at = nullptr);

// Checks the invariants that ceres::Problem would otherwise abort on (node ids in range, no node
// twice in one term, storage sized). Programmer errors: asserts.
void ValidateModel(const Model& model);

}  // namespace drape

#endif  // DRAPE_SRC_MODEL_MODEL_H_
