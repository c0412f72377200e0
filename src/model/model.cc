// BuildModel: from a loaded Scene to nodes, masses, fixed coordinates and the energy terms.
//
// Masses (material):
// - density: kg/m² times each node's lumped area (a quarter of each grid cell to each corner, a
//   third of each triangle to each vertex). A mesh without area — a chain — takes density in kg per
//   metre of line, times each node's lumped length (half of each adjacent segment).
// - node_mass: every node the same mass.
// - total_mass: shared in proportion to lumped area (or length); equally if all are zero.
// Several terms in one energy: a finite_volume material may have material.springs beside it
// (the same families on the same lattice, added to the finite-volume terms), and every material
// may have material.lines (src/model/model.cc AddLines). Each kind of term keeps its own type,
// so summary.json reports each one's energy.
// Regions (regions:, src/model/regions.h): each node's density, finite-volume values and spring
// stiffnesses are its own region's; a spring joins two nodes whose stiffnesses a and b may
// differ: its two halves in series, 2ab/(a + b), tension-only if either node's material is.
// Springs (material.springs): structural = warp links (stiffness `warp`) and weft links (`weft`);
// shear = diagonals with (warp + weft)/2; flexion = skip-one links, warp and weft. Rest lengths:
// `initial` = the distance in the mesh (before any `move`); `zero` = ZeroLengthSpring (never
// compressed, so `tension_only` changes nothing); a given length L scales every spring's initial
// length by L / (mean initial length of the structural links), so that structural springs of a
// uniform mesh get L and diagonals and skip-one springs keep their proportions.
// Fixed: selections are made on the mesh as generated; each `fixed` entry fixes its `dofs` and adds
// its `move` to the start of its nodes (a node in several entries gets the sum of their moves). In
// 2-D (dimension: 2) every node's y is fixed as well.
// Loads: gravity m·g on every node with mass, forces `total` shared equally among the selected
// nodes, `each` on every one, `values` one per selected node in id order, or a `ramp` from `from`
// to `to` (see RampParameters), a `traction` (Pa) or a `pressure` (Pa, along the initial normal)
// times each node's lumped area (AreaForces); one linear potential per loaded node, measured from
// its start. Selections `{region: name}` are the named region's own (resolved by the loader).
// Pressure (loads.pressure) on a closed chain: one PressurePotential per link of the loop, the
// loop oriented so that its initial x–z area is positive (p > 0 inflates). It is a follower load,
// not a constant one, so it is not counted in `applied`.
#include "src/model/model.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cassert>
#include <chrono>
#include <cmath>
#include <limits>
#include <sstream>

#include "costs/constant_force_potential.h"
#include "costs/pressure_potential.h"
#include "costs/spring_stretch.h"
#include "costs/tension_only_spring.h"
#include "costs/zero_length_spring.h"
#include "src/model/contact.h"
#include "src/model/finite_volume.h"
#include "src/model/mesh.h"
#include "src/model/regions.h"
#include "src/model/selection.h"
#include "src/model/self_contact.h"
#include "src/model/stretch_limit.h"
#include "src/scene/solver_methods.h"

namespace drape {

int Model::num_free_dofs() const {
  int count = 0;
  for (char f : fixed) count += f ? 0 : 1;
  return count;
}

std::map<std::string, int> Model::TermCounts() const {
  std::map<std::string, int> counts;
  for (const auto& term : terms) ++counts[term->type()];
  return counts;
}

namespace {

const char* const kAxisNames[3] = {"x", "y", "z"};

// The run's time limit bounds the build of the model too (solver.time_limit, else the method's
// default): Check, called between the stages, stops a build past it with an InputError located at
// the solver section (a huge mesh under a short limit stops near the limit, not minutes later).
class BuildClock {
 public:
  explicit BuildClock(const Scene& scene)
      : scene_(scene),
        limit_(FindSolverMethod(scene.solver.method)
                   ? EffectiveTimeLimit(scene.solver, scene.solver.method)
                   : scene.solver.time_limit.value_or(std::numeric_limits<double>::infinity())),
        start_(std::chrono::steady_clock::now()) {}

  // `done`: what has been built so far, for the message.
  void Check(const std::string& done) const {
    const double elapsed =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    if (!(elapsed > limit_)) return;
    std::ostringstream text;
    text.precision(3);
    text << "building the model took " << elapsed << " s (" << done
         << "), more than the time limit " << limit_ << " s (solver.time_limit"
         << (scene_.solver.time_limit ? "" : ", the method's default")
         << "): raise the time limit or use a coarser mesh (mesh.nodes, mesh.spacing)";
    const Location& where = scene_.solver.where.line > 0 ? scene_.solver.where : scene_.mesh.where;
    throw InputError(where, text.str());
  }

 private:
  const Scene& scene_;
  const double limit_;
  const std::chrono::steady_clock::time_point start_;
};

// Lumped area per node, or lumped length where the mesh has no area (a chain).
std::vector<double> MassWeights(const Mesh& mesh) {
  double area = 0.0;
  for (double a : mesh.area) area += a;
  if (area > 0.0 || mesh.length.empty()) return mesh.area;
  return mesh.length;
}

// A region's density (regions:) replaces material.density for its nodes; node_mass and
// total_mass take none (the loader refuses it).
std::vector<double> NodeMasses(const NodeMaterials& materials, const Mesh& mesh) {
  const MaterialSpec& material = materials.materials[0];
  const int n = static_cast<int>(mesh.nodes.size());
  const std::vector<double> weights = MassWeights(mesh);
  std::vector<double> mass(n, material.mass_value);
  switch (material.mass_kind) {
    case MaterialSpec::MassKind::kDensity:
      for (int k = 0; k < n; ++k) mass[k] = materials.at(k).mass_value * weights[k];
      break;
    case MaterialSpec::MassKind::kNodeMass:
      break;
    case MaterialSpec::MassKind::kTotalMass: {
      double sum = 0.0;
      for (double w : weights) sum += w;
      for (int k = 0; k < n; ++k) {
        mass[k] = material.mass_value * (sum > 0.0 ? weights[k] / sum : 1.0 / n);
      }
      break;
    }
  }
  return mass;
}

// Fixes the selected coordinates and moves the selected nodes to their start.
void ApplyFixed(const Scene& scene, const Mesh& mesh, Model* model) {
  if (scene.dimension == 2) {
    for (int k = 0; k < model->num_nodes; ++k) model->fixed[3 * k + 1] = 1;
  }
  for (const FixedSpec& spec : scene.fixed) {
    for (int node : SelectNodes(spec.nodes, mesh)) {
      for (int c = 0; c < 3; ++c) {
        if (spec.dofs[c]) model->fixed[3 * node + c] = 1;
        model->positions[3 * node + c] += spec.move[c];
      }
    }
  }
}

// In two dimensions nodes move in x–z only: the mesh must lie in one plane y = constant.
void CheckPlanarFor2d(const Scene& scene, const Mesh& mesh) {
  if (scene.dimension != 2) return;
  double low = mesh.nodes[0].y(), high = low;
  for (const auto& p : mesh.nodes) {
    low = std::min(low, p.y());
    high = std::max(high, p.y());
  }
  double size = 0.0;
  for (const auto& p : mesh.nodes) size = std::max(size, (p - mesh.nodes[0]).norm());
  if (high - low > 1e-12 * size) {
    throw InputError(scene.mesh.where,
                     "a 2-D scene (dimension: 2) needs a mesh in one x-z plane (all nodes at the "
                     "same y): use a chain, a grid with nodes: [n, 1], or plane: xz");
  }
}

// One spring of initial length × rest_scale: zero-length, tension-only or two-sided.
void AddSpring(const std::string& type, const Link& link, double stiffness, bool tension_only,
               const SpringsSpec& springs, double rest_scale, const Mesh& mesh, Model* model) {
  if (!(stiffness > 0.0)) return;
  const std::vector<int> nodes{link[0], link[1]};
  const double rest = rest_scale * (mesh.nodes[link[1]] - mesh.nodes[link[0]]).norm();
  if (springs.rest_length == SpringsSpec::RestLength::kZero) {
    model->terms.push_back(MakeTerm(type, nodes, ZeroLengthSpring::Create(stiffness)));
  } else if (tension_only) {
    model->terms.push_back(MakeTerm(type, nodes, TensionOnlySpring::Create(stiffness, rest)));
  } else {
    model->terms.push_back(MakeTerm(type, nodes, SpringStretch::Create(stiffness, rest)));
  }
}

// The stiffness of a link between two nodes of stiffness a and b (regions): its two halves in
// series, 2ab/(a + b) — a where both are a, 0 where either is 0.
double SeriesStiffness(double a, double b) {
  if (a == b) return a;
  return a > 0.0 && b > 0.0 ? 2.0 * a * b / (a + b) : 0.0;
}

// The stiffness a family gives one node (warp or weft; shear: their mean), 0 if the node's
// material has none of that family.
double FamilyStiffness(const SpringFamilySpec& family, int direction) {
  if (!family.present) return 0.0;
  if (direction == 0) return family.warp;
  if (direction == 1) return family.weft;
  return 0.5 * (family.warp + family.weft);
}

struct SpringFactory {
  const NodeMaterials& materials;
  const SpringsSpec& springs;  // the scene's: rest length
  double rest_scale;           // rest length = rest_scale × initial length (kInitial and kGiven)

  void Add(const std::string& type, const std::vector<Link>& links,
           SpringFamilySpec SpringsSpec::*family, int direction, const Mesh& mesh,
           Model* model) const {
    for (const Link& link : links) {
      const SpringsSpec& a = materials.at(link[0]).springs;
      const SpringsSpec& b = materials.at(link[1]).springs;
      const double stiffness = SeriesStiffness(FamilyStiffness(a.*family, direction),
                                               FamilyStiffness(b.*family, direction));
      AddSpring(type, link, stiffness, a.tension_only || b.tension_only, springs, rest_scale, mesh,
                model);
    }
  }
};

// L / (mean initial length of the structural links) for a given rest length L, else 1.
double RestScale(const SpringsSpec& springs, const Mesh& mesh) {
  if (springs.rest_length != SpringsSpec::RestLength::kGiven) return 1.0;
  double sum = 0.0;
  int count = 0;
  for (const auto* links : {&mesh.warp, &mesh.weft}) {
    for (const Link& link : *links) {
      sum += (mesh.nodes[link[1]] - mesh.nodes[link[0]]).norm();
      ++count;
    }
  }
  return count > 0 && sum > 0.0 ? springs.rest_length_value / (sum / count) : 1.0;
}

// The spring families of material.springs, with each node's stiffness from its region.
void AddSprings(const NodeMaterials& materials, const Mesh& mesh, Model* model) {
  const SpringsSpec& springs = materials.materials[0].springs;
  const SpringFactory factory{materials, springs, RestScale(springs, mesh)};
  factory.Add("structural", mesh.warp, &SpringsSpec::structural, 0, mesh, model);
  factory.Add("structural", mesh.weft, &SpringsSpec::structural, 1, mesh, model);
  factory.Add("shear", mesh.shear, &SpringsSpec::shear, 2, mesh, model);
  factory.Add("flexion", mesh.flexion_warp, &SpringsSpec::flexion, 0, mesh, model);
  factory.Add("flexion", mesh.flexion_weft, &SpringsSpec::flexion, 1, mesh, model);
}

// material.lines: a "line" spring (rest length: the initial distance) on every structural link
// — lattice neighbours along the warp or the weft — both of whose nodes the line selects.
void AddLines(const MaterialSpec& material, const Mesh& mesh, Model* model) {
  for (const SpringLineSpec& line : material.lines) {
    std::vector<char> selected(mesh.nodes.size(), 0);
    for (int node : SelectNodes(line.nodes, mesh)) selected[node] = 1;
    const size_t before = model->terms.size();
    for (const auto* links : {&mesh.warp, &mesh.weft}) {
      for (const Link& link : *links) {
        if (!selected[link[0]] || !selected[link[1]]) continue;
        const double rest = (mesh.nodes[link[1]] - mesh.nodes[link[0]]).norm();
        const std::vector<int> nodes{link[0], link[1]};
        model->terms.push_back(
            line.tension_only
                ? MakeTerm("line", nodes, TensionOnlySpring::Create(line.stiffness, rest))
                : MakeTerm("line", nodes, SpringStretch::Create(line.stiffness, rest)));
      }
    }
    if (model->terms.size() == before) {
      throw InputError(line.nodes.where,
                       "the line's selection holds no two neighbouring nodes (lattice neighbours "
                       "along the warp or the weft), so it has no spring");
    }
  }
}

// A constant force on one node as a linear potential measured from the node's start,
// E = −f·(x − x₀) ≥ −|f| |x − x₀|. The least-squares shift |f| × 2 × size keeps sqrt(2(E + shift))
// real while the node stays within twice the fabric's size of its start; a step beyond that is
// not evaluable and Ceres rejects it (src/model/term.h, src/solvers/solver_ceres_least_squares.cc).
void AddConstantForce(const std::string& type, int node, const Eigen::Vector3d& force,
                      Model* model) {
  if (force.norm() == 0.0) return;
  const double* reference = model->position(node).data();
  const double shift = force.norm() * 2.0 * model->size;
  model->terms.push_back(
      MakeTerm(type, {node}, ConstantForcePotential::Create(force.data(), reference), shift));
  NodeAt(model->applied, node) += force;
}

// The place of each selected node along the selection, from 0 at its first node (lowest id) to 1
// at its last: the projection of the node's mesh position on the segment between those two,
// clamped to [0, 1]. A selection of one node, or whose ends coincide, gets 0 everywhere.
std::vector<double> RampParameters(const std::vector<int>& nodes, const Mesh& mesh) {
  const Eigen::Vector3d start = mesh.nodes[nodes.front()];
  const Eigen::Vector3d span = mesh.nodes[nodes.back()] - start;
  const double length_squared = span.squaredNorm();
  std::vector<double> parameters;
  for (int node : nodes) {
    const double s =
        length_squared > 0.0 ? (mesh.nodes[node] - start).dot(span) / length_squared : 0.0;
    parameters.push_back(std::clamp(s, 0.0, 1.0));
  }
  return parameters;
}

// The unit normal of the initial surface at each node: the sum of its triangles' area vectors
// (right-hand rule over each triangle's node order), normalised; zero where a node has none.
std::vector<Eigen::Vector3d> NodeNormals(const Mesh& mesh) {
  std::vector<Eigen::Vector3d> normals(mesh.nodes.size(), Eigen::Vector3d::Zero());
  for (const auto& t : mesh.triangles) {
    const Eigen::Vector3d area_vector =
        (mesh.nodes[t[1]] - mesh.nodes[t[0]]).cross(mesh.nodes[t[2]] - mesh.nodes[t[0]]);
    for (int node : t) normals[node] += area_vector;
  }
  for (auto& normal : normals) {
    if (normal.norm() > 0.0) normal.normalize();
  }
  return normals;
}

// `traction` (Pa) or `pressure` (Pa along the initial normal) on each selected node, times the
// node's lumped area (its lumped length on a chain: then N/m). Dead loads: their direction and
// area are the initial surface's.
std::vector<Eigen::Vector3d> AreaForces(const ForceSpec& spec, const std::vector<int>& nodes,
                                        const Mesh& mesh) {
  const std::vector<double> weights = MassWeights(mesh);
  std::vector<Eigen::Vector3d> normals;
  if (spec.kind == ForceSpec::Kind::kPressure) {
    if (mesh.triangles.empty()) {
      throw InputError(spec.where,
                       "a pressure on selected nodes needs a surface mesh (triangles); a closed "
                       "2-D chain takes loads.pressure, a follower pressure on the whole loop");
    }
    normals = NodeNormals(mesh);
  }
  std::vector<Eigen::Vector3d> forces;
  for (int node : nodes) {
    const Eigen::Vector3d per_area = spec.kind == ForceSpec::Kind::kPressure
                                         ? Eigen::Vector3d(spec.pressure * normals[node])
                                         : spec.value;
    forces.push_back(weights[node] * per_area);
  }
  return forces;
}

// The force on each selected node, in the order of `nodes`.
std::vector<Eigen::Vector3d> NodeForces(const ForceSpec& spec, const std::vector<int>& nodes,
                                        const Mesh& mesh) {
  const size_t n = nodes.size();
  switch (spec.kind) {
    case ForceSpec::Kind::kTraction:
    case ForceSpec::Kind::kPressure:
      return AreaForces(spec, nodes, mesh);
    case ForceSpec::Kind::kTotal:
      return std::vector<Eigen::Vector3d>(n, spec.value / static_cast<double>(n));
    case ForceSpec::Kind::kEach:
      return std::vector<Eigen::Vector3d>(n, spec.value);
    case ForceSpec::Kind::kValues:
      if (spec.values.size() != n) {
        throw InputError(spec.values_where,
                         "gives " + std::to_string(spec.values.size()) +
                             " forces but the selection has " + std::to_string(n) +
                             " nodes: give one [fx, fy, fz] per selected node, in id order");
      }
      return spec.values;
    case ForceSpec::Kind::kRamp: {
      std::vector<Eigen::Vector3d> forces;
      for (double s : RampParameters(nodes, mesh)) {
        forces.push_back((1.0 - s) * spec.value + s * spec.ramp_to);
      }
      return forces;
    }
  }
  return {};
}

// The x–z centre of the loop's nodes and the loop's links, oriented so that its area is positive.
std::vector<Link> OrientedLoop(const Mesh& mesh, Eigen::Vector2d* centre) {
  *centre = Eigen::Vector2d::Zero();
  for (const Link& link : mesh.loop) {
    *centre += Eigen::Vector2d(mesh.nodes[link[0]].x(), mesh.nodes[link[0]].z());
  }
  *centre /= static_cast<double>(mesh.loop.size());
  double twice_area = 0.0;
  for (const Link& link : mesh.loop) {
    const Eigen::Vector3d a = mesh.nodes[link[0]], b = mesh.nodes[link[1]];
    twice_area += (a.x() - centre->x()) * (b.z() - centre->y()) -
                  (b.x() - centre->x()) * (a.z() - centre->y());
  }
  std::vector<Link> loop = mesh.loop;
  if (twice_area < 0.0) {
    for (Link& link : loop) link = {link[1], link[0]};
  }
  return loop;
}

void AddPressure(const Scene& scene, const Mesh& mesh, Model* model) {
  if (!scene.loads.pressure) return;
  const PressureSpec& spec = *scene.loads.pressure;
  if (mesh.loop.empty()) {
    throw InputError(spec.where, "pressure needs a closed profile: a chain mesh with closed: true");
  }
  if (scene.dimension != 2) {
    throw InputError(spec.where,
                     "pressure acts on a closed profile in the x-z plane: set dimension: 2");
  }
  if (spec.pressure == 0.0) return;
  Eigen::Vector2d centre;
  for (const Link& link : OrientedLoop(mesh, &centre)) {
    model->terms.push_back(
        MakeTerm("pressure", {link[0], link[1]},
                 PressurePotential::Create(spec.pressure, centre.x(), centre.y()),
                 std::abs(spec.pressure) * model->size * model->size));
  }
}

void AddLoads(const Scene& scene, const Mesh& mesh, Model* model) {
  if (scene.loads.gravity) {
    for (int k = 0; k < model->num_nodes; ++k) {
      if (model->mass[k] > 0.0)
        AddConstantForce("gravity", k, model->mass[k] * *scene.loads.gravity, model);
    }
  }
  for (const ForceSpec& spec : scene.loads.forces) {
    const std::vector<int> nodes = SelectNodes(spec.nodes, mesh);
    const std::vector<Eigen::Vector3d> forces = NodeForces(spec, nodes, mesh);
    for (size_t k = 0; k < nodes.size(); ++k) AddConstantForce("load", nodes[k], forces[k], model);
  }
  AddPressure(scene, mesh, model);
}

// Whether some node, carried along `direction` from its start, meets one of the obstacles: sphere
// tracing on the signed distance, out to 1000 × the distance scale of the scene.
bool SomeObstacleOnThePath(const Scene& scene, const Model& model,
                           const Eigen::Vector3d& direction) {
  constexpr int kMaxSteps = 400;
  for (const ObstacleSpec& obstacle : scene.obstacles) {
    for (int k = 0; k < model.num_nodes; ++k) {
      const Eigen::Vector3d start = model.position(k);
      const double reach = 1e3 * (model.size + std::abs(ObstacleDistance(obstacle, start.data())));
      double travelled = 0.0;
      for (int step = 0; step < kMaxSteps && travelled <= reach; ++step) {
        const Eigen::Vector3d at = start + travelled * direction;
        const double distance = ObstacleDistance(obstacle, at.data());
        if (distance <= 1e-9 * model.size) return true;
        travelled += distance;
      }
    }
  }
  return false;
}

// A node that starts inside an obstacle's body would be pushed out by the contact penalty with
// a force far beyond the loads: refused, at the obstacle.
void CheckNoNodeStartsInside(const Scene& scene, const Model& model) {
  for (const ObstacleSpec& obstacle : scene.obstacles) {
    for (int k = 0; k < model.num_nodes; ++k) {
      const double distance = ObstacleDistance(obstacle, model.position(k).data());
      if (distance < -1e-9 * model.size) {
        std::ostringstream text;
        text << "node " << k << " starts inside this obstacle (" << -distance
             << " m deep): move the fabric or the obstacle";
        throw InputError(obstacle.where, text.str());
      }
    }
  }
}

// Gravity or loads along a direction in which nothing is fixed (and no obstacle on the way holds
// the fabric) would translate the whole fabric without end: the energy has no minimum.
void CheckHasMinimum(const Scene& scene, const Model& model) {
  for (int c = 0; c < 3; ++c) {
    bool fixed = false;
    double net = 0.0, magnitude = 0.0;
    for (int k = 0; k < model.num_nodes; ++k) {
      fixed = fixed || model.fixed[3 * k + c];
      net += model.applied[3 * k + c];
      magnitude += std::abs(model.applied[3 * k + c]);
    }
    if (fixed || magnitude == 0.0) continue;
    const std::string axis = kAxisNames[c];
    if (std::abs(net) > 1e-12 * magnitude) {
      Eigen::Vector3d direction = Eigen::Vector3d::Zero();
      direction[c] = net > 0.0 ? 1.0 : -1.0;
      if (SomeObstacleOnThePath(scene, model, direction)) continue;
      // An obstacle's friction may hold the fabric in any direction; where it does not, the solve
      // runs away (not converged).
      if (HasObstacleFriction(scene.obstacles)) continue;
      throw InputError(scene.loads.where,
                       "gravity/loads act along " + axis + " but no node is fixed along " + axis +
                           " and no obstacle holds the fabric: the energy has no minimum (fix "
                           "some nodes)");
    }
    if (!scene.obstacles.empty()) continue;  // sliding along an obstacle: left to the solver
    throw InputError(scene.loads.where, "loads act along " + axis + " but no node is fixed along " +
                                            axis + ": the fabric is free to slide along " + axis +
                                            " and its equilibrium is not unique (fix some nodes)");
  }
}

// A pressure alone pushes on the profile in balance; what holds the profile in place must be
// fixed along x and z, else it floats freely in the plane.
void CheckPressureHeld(const Scene& scene, const Model& model) {
  if (!scene.loads.pressure || scene.loads.pressure->pressure == 0.0) return;
  for (int c : {0, 2}) {
    bool fixed = false;
    for (int k = 0; k < model.num_nodes; ++k) fixed = fixed || model.fixed[3 * k + c];
    if (!fixed) {
      throw InputError(scene.loads.pressure->where,
                       std::string("the pressurised profile is free to slide along ") +
                           kAxisNames[c] + ": fix some nodes along " + kAxisNames[c]);
    }
  }
}

}  // namespace

Model BuildModel(const Scene& scene, const std::vector<double>* friction_reference,
                 const std::vector<double>* pushed_at) {
  const BuildClock clock(scene);
  const Mesh mesh = BuildMesh(scene.mesh);
  const std::string nodes = std::to_string(mesh.nodes.size()) + " nodes";
  clock.Check("the mesh of " + nodes);
  CheckPlanarFor2d(scene, mesh);
  Model model;
  model.dimension = scene.dimension;
  model.num_nodes = static_cast<int>(mesh.nodes.size());
  model.positions.resize(model.num_dofs());
  for (int k = 0; k < model.num_nodes; ++k) {
    model.position(k) = Eigen::Vector3d(mesh.nodes[k][0], mesh.nodes[k][1], mesh.nodes[k][2]);
  }
  model.fixed.assign(model.num_dofs(), 0);
  model.applied.assign(model.num_dofs(), 0.0);
  const NodeMaterials materials = AssignMaterials(scene, mesh);
  model.region_counts = materials.counts;
  model.mass = NodeMasses(materials, mesh);
  ApplyFixed(scene, mesh, &model);
  model.initial = model.positions;
  model.size = BoundingDiagonal(
      Eigen::Map<const Eigen::Matrix3Xd>(model.positions.data(), 3, model.num_nodes));
  if (!(model.size > 0.0)) {  // every node moved onto one point: fall back to the mesh's size
    Eigen::Matrix3Xd mesh_positions(3, mesh.nodes.size());
    for (size_t k = 0; k < mesh.nodes.size(); ++k) mesh_positions.col(k) = mesh.nodes[k];
    model.size = BoundingDiagonal(mesh_positions);
  }
  model.grid_index = mesh.grid_index;
  model.triangles = mesh.triangles;
  model.fringe = mesh.fringe;
  model.edges = mesh.lines;

  switch (scene.material.model) {
    case MaterialModel::kSprings:
      AddSprings(materials, mesh, &model);
      break;
    case MaterialModel::kFiniteVolume: {
      std::vector<const FiniteVolumeSpec*> of_node(mesh.nodes.size());
      for (size_t k = 0; k < of_node.size(); ++k) {
        of_node[k] = &materials.at(static_cast<int>(k)).finite_volume;
      }
      assert(!friction_reference || friction_reference->size() == model.positions.size());
      AddFiniteVolumeTerms(of_node, mesh, &model,
                           friction_reference ? friction_reference->data() : nullptr);
      // Springs given beside the finite-volume terms.
      if (scene.material.springs.present) AddSprings(materials, mesh, &model);
      break;
    }
  }
  if (scene.material.springs.stretch_limit) {
    AddStretchLimitTerms(*scene.material.springs.stretch_limit, &model);
  }
  AddLines(scene.material, mesh, &model);
  clock.Check("the elastic terms of " + nodes);
  AddLoads(scene, mesh, &model);
  if (!scene.obstacles.empty()) {
    AddContactTerms(scene.obstacles, scene.contact, &model);
    AddObstacleFrictionTerms(friction_reference ? *friction_reference : model.initial, pushed_at,
                             &model);
  }
  SetUpSelfContact(scene, &model);  // last: its terms are replaced as the fabric moves
  clock.Check("the loads and contact terms of " + nodes);
  CheckNoNodeStartsInside(scene, model);
  CheckHasMinimum(scene, model);
  CheckPressureHeld(scene, model);
  ValidateModel(model);
  clock.Check("the checks of the model of " + nodes);
  return model;
}

}  // namespace drape
