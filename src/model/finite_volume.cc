#include "src/model/finite_volume.h"

#include <array>
#include <cassert>
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "costs/fv_bending.h"
#include "costs/fv_bending_friction.h"
#include "costs/fv_bending_friction_step.h"
#include "costs/fv_cell_shear.h"
#include "costs/fv_membrane.h"
#include "costs/fv_shear_friction.h"
#include "costs/fv_twist.h"
#include "costs/spring_stretch.h"

namespace drape {

MembraneRigidities PlaneStressRigidities(const FiniteVolumeSpec& spec) {
  const double factor = 1.0 - spec.nu_warp * spec.nu_weft;
  return {spec.E_warp / factor, spec.E_weft / factor, spec.nu_warp * spec.E_weft / factor, spec.G};
}

namespace {

void CheckMaterial(const FiniteVolumeSpec& spec) {
  auto fail = [&spec](const std::string& what) {
    throw InputError(spec.where, "finite_volume: " + what);
  };
  if (!(spec.E_warp > 0.0) || !(spec.E_weft > 0.0)) fail("E_warp and E_weft must be positive");
  if (spec.G < 0.0 || spec.D_warp < 0.0 || spec.D_weft < 0.0) {
    fail("G, D_warp and D_weft must not be negative");
  }
  if (!(spec.nu_warp * spec.nu_weft < 1.0)) fail("nu_warp * nu_weft must be below 1");
  const MembraneRigidities e = PlaneStressRigidities(spec);
  if (e.e1 * e.e2 < e.e12 * e.e12) {
    fail("nu_warp^2 * E_weft must not exceed E_warp (the membrane energy would be indefinite)");
  }
  if (spec.D_12 * spec.D_12 > spec.D_warp * spec.D_weft) {
    fail("D_12^2 must not exceed D_warp * D_weft (the bending energy would be indefinite)");
  }
  if (!(spec.D_66 >= 0.0)) fail("D_66 must not be negative");
}

// Node ids by lattice position: (i, j) in [0, nu) × [0, nv) from Mesh::grid_index, -1 where the
// lattice has no node (outside a circle mesh's disc, or beyond the edge).
class Lattice {
 public:
  Lattice(int nu, int nv) : nu_(nu), nv_(nv), ids_(static_cast<size_t>(nu) * nv, -1) {}

  bool InRange(int i, int j) const { return i >= 0 && j >= 0 && i < nu_ && j < nv_; }
  int At(int i, int j) const { return InRange(i, j) ? ids_[Index(i, j)] : -1; }
  // False if (i, j) is out of range or taken already.
  bool Set(int i, int j, int id) {
    if (!InRange(i, j) || ids_[Index(i, j)] >= 0) return false;
    ids_[Index(i, j)] = id;
    return true;
  }

 private:
  size_t Index(int i, int j) const { return static_cast<size_t>(j) * nu_ + i; }
  int nu_, nv_;
  std::vector<int> ids_;
};

// The lattice of a grid or circle mesh whose nodes all carry area; throws InputError otherwise.
Lattice CheckedLattice(const FiniteVolumeSpec& spec, const Mesh& mesh, const Model& model) {
  const int n = static_cast<int>(mesh.nodes.size());
  bool ok = mesh.nu > 0 && mesh.nv > 0 && static_cast<int>(mesh.grid_index.size()) == n &&
            static_cast<int>(mesh.area.size()) == n && model.num_nodes == n;
  Lattice lattice(ok ? mesh.nu : 0, ok ? mesh.nv : 0);
  for (int k = 0; ok && k < n; ++k) {
    ok = mesh.area[k] > 0.0 && lattice.Set(mesh.grid_index[k][0], mesh.grid_index[k][1], k);
  }
  if (!ok) {
    throw InputError(spec.where,
                     "the finite_volume material needs a grid or circle mesh with area "
                     "(mesh.kind: grid or circle; a 2-D strip is a grid with nodes: [n, 1] and "
                     "size: [length, width])");
  }
  return lattice;
}

// The material of each node's control volume.
using NodeSpecs = std::vector<const FiniteVolumeSpec*>;

double RestDistance(const Mesh& mesh, int a, int b) {
  return (mesh.nodes[b] - mesh.nodes[a]).norm();
}

// The coordinates of node k in the friction's reference state (3 per node; null: the flat state).
const double* At(const double* reference, int k) { return reference + 3 * k; }

// A neighbour across a control volume, which signs its curvature in a load step
// (FvBendingFrictionStep's d and σ); node -1 where there is none (a strip).
struct Across {
  int node = -1;
  double sign = 1.0;
};

// The friction term of one direction of control volume `along[1]`, nodes `along` = {a, P, b} (none
// without friction): the monotone form's, or, with spec.friction_load_steps, a load step's, whose
// curvature takes its sign from `across` = {d, σ}, a neighbour across the volume, and whose kink
// is at the reference's curvature. The least-squares shift (src/model/term.h), H A / l, the energy
// at a curvature of 1/l from the kink, keeps the ceres-* solvers' residual √(2 (E + shift)) smooth
// at the kink, where E = 0.
void AddBendingFriction(double friction, const FiniteVolumeSpec& spec,
                        const std::vector<int>& along, const Across& across, double size,
                        double area, const double* reference, Model* model) {
  if (!(friction > 0.0)) return;
  const double shift = friction * area / size;
  if (spec.friction_load_steps == 0) {
    model->terms.push_back(MakeTerm(
        "fv_bending_friction", along,
        FvBendingFriction::Create(friction, size, area, spec.bending_friction_smoothing), shift));
    return;
  }
  if (across.node < 0) {
    throw InputError(spec.where,
                     "finite_volume.friction_load_steps: the incremental friction signs a "
                     "curvature by the direction across the fabric, which a strip (a single row "
                     "or column of nodes) has not; use a grid with at least two rows");
  }
  double previous = 0.0;  // the flat state's, or the reference's (0 where d sits on P there)
  if (reference) {
    FvBendingFrictionStep::SignedCurvature(At(reference, along[0]), At(reference, along[1]),
                                           At(reference, along[2]), At(reference, across.node),
                                           size, across.sign, &previous);
  }
  model->terms.push_back(
      MakeTerm("fv_bending_friction_step", {along[0], along[1], along[2], across.node},
               FvBendingFrictionStep::Create(friction, size, area, spec.bending_friction_smoothing,
                                             previous, across.sign),
               shift));
}

// A single row (or column) of nodes: a strip bending in one direction. Each link's membrane
// spring is its two halves, each of the modulus of its own node's control volume.
void AddStrip(const NodeSpecs& of_node, const Mesh& mesh, Model* model) {
  const bool row = mesh.nv == 1;
  const int count = row ? mesh.nu : mesh.nv;
  const int step = row ? 1 : mesh.nu;
  const auto modulus = [&](int node) {
    return row ? of_node[node]->E_warp : of_node[node]->E_weft;
  };
  const auto rigidity = [&](int node) {
    return row ? of_node[node]->D_warp : of_node[node]->D_weft;
  };
  std::vector<double> size(count, 0.0);  // lumped length of each control volume
  for (int k = 0; k + 1 < count; ++k) {
    const double half = 0.5 * RestDistance(mesh, k * step, (k + 1) * step);
    size[k] += half;
    size[k + 1] += half;
  }
  for (int k = 0; k + 1 < count; ++k) {
    const int a = k * step, b = (k + 1) * step;
    const double length = RestDistance(mesh, a, b);
    const double width_a = mesh.area[a] / size[k], width_b = mesh.area[b] / size[k + 1];
    double stiffness = 0.0;  // E w / l, the two halves of the link in parallel over its length
    if (modulus(a) == modulus(b)) {
      const double area = 0.5 * length * (width_a + width_b);
      stiffness = modulus(a) * area / (length * length);
    } else {
      stiffness = 0.5 * (modulus(a) * width_a + modulus(b) * width_b) / length;
    }
    model->terms.push_back(
        MakeTerm("fv_membrane", {a, b}, SpringStretch::Create(stiffness, length)));
  }
  for (int k = 1; k + 1 < count; ++k) {
    const int a = (k - 1) * step, p = k * step, b = (k + 1) * step;
    const FiniteVolumeSpec& spec = *of_node[p];
    AddBendingFriction(row ? spec.bending_friction_warp : spec.bending_friction_weft, spec,
                       {a, p, b}, Across{}, size[k], mesh.area[p], nullptr, model);
    if (!(rigidity(p) > 0.0)) continue;
    model->terms.push_back(MakeTerm("fv_bending", {a, p, b},
                                    FvBendingEdge::Create(rigidity(p), size[k], mesh.area[p])));
  }
}

// Neighbour ids of node (i, j) along the warp (W, E: i ∓ 1) and weft (S, N: j ∓ 1), -1 where
// the lattice has no node (beyond the edge, outside a circle's disc).
struct Neighbours {
  int w, e, s, n;
};

Neighbours NeighboursOf(const Lattice& lattice, int i, int j) {
  return {lattice.At(i - 1, j), lattice.At(i + 1, j), lattice.At(i, j - 1), lattice.At(i, j + 1)};
}

// The neighbour across a control volume whose `low` and `high` neighbours are given (-1: none).
Across AcrossOf(int low, int high) {
  if (high >= 0) return {high, 1.0};
  if (low >= 0) return {low, -1.0};
  return {};
}

void AddBending(const FiniteVolumeSpec& spec, const Mesh& mesh, int p, const Neighbours& nb,
                const double* reference, Model* model) {
  const bool warp = nb.w >= 0 && nb.e >= 0, weft = nb.s >= 0 && nb.n >= 0;
  const double area = mesh.area[p];
  const double size1 = warp ? 0.5 * (RestDistance(mesh, nb.w, p) + RestDistance(mesh, p, nb.e)) : 0;
  const double size2 = weft ? 0.5 * (RestDistance(mesh, nb.s, p) + RestDistance(mesh, p, nb.n)) : 0;
  if (warp) {
    AddBendingFriction(spec.bending_friction_warp, spec, {nb.w, p, nb.e}, AcrossOf(nb.s, nb.n),
                       size1, area, reference, model);
  }
  if (weft) {
    AddBendingFriction(spec.bending_friction_weft, spec, {nb.s, p, nb.n}, AcrossOf(nb.w, nb.e),
                       size2, area, reference, model);
  }
  if (warp && weft) {
    if (spec.D_warp > 0.0 || spec.D_weft > 0.0) {
      model->terms.push_back(
          MakeTerm("fv_bending", {nb.w, p, nb.e, nb.s, nb.n},
                   FvBending::Create(spec.D_warp, spec.D_weft, spec.D_12, size1, size2, area)));
    }
  } else if (warp && spec.D_warp > 0.0) {
    model->terms.push_back(
        MakeTerm("fv_bending", {nb.w, p, nb.e}, FvBendingEdge::Create(spec.D_warp, size1, area)));
  } else if (weft && spec.D_weft > 0.0) {
    model->terms.push_back(
        MakeTerm("fv_bending", {nb.s, p, nb.n}, FvBendingEdge::Create(spec.D_weft, size2, area)));
  }
}

// Whether the quarter of control volume p between its arms to a (warp) and b (weft) lies in a
// whole lattice cell: the cell's fourth corner, at a's column and b's row, is a node.
bool InWholeCell(const Lattice& lattice, const Mesh& mesh, int a, int b) {
  return lattice.At(mesh.grid_index[a][0], mesh.grid_index[b][1]) >= 0;
}

// The four quarters of control volume p: membrane, and the shear friction where the fabric has it.
// With `finite_volume.cell_shear`, a quarter in a whole cell leaves its shear to the cell's
// FvCellShear (AddCellShear) and keeps its stretch. The friction's least-squares shift, HG A_q, its
// energy at a shear angle of 1 rad, keeps the ceres-* residual √(2 (E + shift)) smooth at rest,
// where E = 0 (as AddBendingFriction's).
void AddMembrane(const MembraneRigidities& e, const FiniteVolumeSpec& spec, bool cell_shear,
                 const Lattice& lattice, const Mesh& mesh, int p, const Neighbours& nb,
                 const double* reference, Model* model) {
  for (int a : {nb.e, nb.w}) {
    for (int b : {nb.n, nb.s}) {
      if (a < 0 || b < 0) continue;
      const double rest_a = RestDistance(mesh, p, a), rest_b = RestDistance(mesh, p, b);
      const double g = cell_shear && InWholeCell(lattice, mesh, a, b) ? 0.0 : e.g;
      model->terms.push_back(MakeTerm("fv_membrane", {p, a, b},
                                      FvMembrane::Create(e.e1, e.e2, e.e12, g, rest_a, rest_b)));
      if (!(spec.shear_friction > 0.0)) continue;
      double previous = 0.0;  // the rest state's, or the reference's (0 where it has none)
      if (reference && spec.friction_load_steps > 0) {
        FvShearFriction::ShearAngleOf(At(reference, p), At(reference, a), At(reference, b),
                                      &previous);
      }
      model->terms.push_back(
          MakeTerm("fv_shear_friction", {p, a, b},
                   FvShearFriction::Create(spec.shear_friction, rest_a, rest_b,
                                           spec.shear_friction_smoothing, previous),
                   spec.shear_friction * rest_a * rest_b / 4.0));
    }
  }
}

// The lattice's cells (i, j)–(i+1, j+1) whose four corners are all nodes, each as its corners
// P, E, N, C (fv_twist.h).
std::vector<std::array<int, 4>> LatticeCells(const Lattice& lattice, const Mesh& mesh) {
  std::vector<std::array<int, 4>> cells;
  for (int p = 0; p < static_cast<int>(mesh.nodes.size()); ++p) {
    const int i = mesh.grid_index[p][0], j = mesh.grid_index[p][1];
    const std::array<int, 4> cell = {p, lattice.At(i + 1, j), lattice.At(i, j + 1),
                                     lattice.At(i + 1, j + 1)};
    if (cell[1] >= 0 && cell[2] >= 0 && cell[3] >= 0) cells.push_back(cell);
  }
  return cells;
}

// The twist of every cell (costs/fv_twist.h). Each node's control volume is shared equally among
// the cells it is a corner of (four inside the fabric, fewer at its edge), so that the cells'
// areas add up to the fabric's (the control volumes' sum) and each part of the area carries the D66
// of its own node's material: weight = Σ_corners D66_k A_k / (cells at k).
void AddTwist(const NodeSpecs& of_node, const Lattice& lattice, const Mesh& mesh, Model* model) {
  const std::vector<std::array<int, 4>> cells = LatticeCells(lattice, mesh);
  std::vector<int> cells_at(mesh.nodes.size(), 0);
  for (const auto& cell : cells) {
    for (int node : cell) ++cells_at[node];
  }
  for (const auto& [p, e, n, c] : cells) {
    double weight = 0.0;
    for (int node : {p, e, n, c}) weight += of_node[node]->D_66 * mesh.area[node] / cells_at[node];
    if (!(weight > 0.0)) continue;
    model->terms.push_back(
        MakeTerm("fv_twist", {p, e, n, c},
                 FvTwist::Create(weight, RestDistance(mesh, p, e), RestDistance(mesh, p, n))));
  }
}

// With `finite_volume.cell_shear`, the shear of every whole cell at its centre
// (costs/fv_cell_shear.h): each corner's quarter of the cell carries the G of its own node's
// material, so the cell's G_c A_c = Σ_corners G_k A_c / 4.
void AddCellShear(const NodeSpecs& of_node, const Lattice& lattice, const Mesh& mesh,
                  Model* model) {
  for (const auto& [p, e, n, c] : LatticeCells(lattice, mesh)) {
    double g = 0.0;
    for (int node : {p, e, n, c}) g += of_node[node]->G / 4.0;
    if (!(g > 0.0)) continue;
    const double area = RestDistance(mesh, p, e) * RestDistance(mesh, p, n);
    model->terms.push_back(MakeTerm("fv_cell_shear", {p, e, n, c}, FvCellShear::Create(g, area)));
  }
}

}  // namespace

void AddFiniteVolumeTerms(const FiniteVolumeSpec& spec, const Mesh& mesh, Model* model,
                          const double* friction_reference) {
  AddFiniteVolumeTerms(NodeSpecs(mesh.nodes.size(), &spec), mesh, model, friction_reference);
}

void AddFiniteVolumeTerms(const std::vector<const FiniteVolumeSpec*>& of_node, const Mesh& mesh,
                          Model* model, const double* friction_reference) {
  assert(of_node.size() == mesh.nodes.size() && !of_node.empty());
  std::map<const FiniteVolumeSpec*, MembraneRigidities> rigidities;
  for (const FiniteVolumeSpec* spec : of_node) {
    if (rigidities.count(spec) > 0) continue;
    CheckMaterial(*spec);
    rigidities[spec] = PlaneStressRigidities(*spec);
  }
  const Lattice lattice = CheckedLattice(*of_node[0], mesh, *model);
  // One choice for the whole fabric: a region copies the base material and cannot set it.
  const bool cell_shear = of_node[0]->cell_shear;
  const int n = static_cast<int>(mesh.nodes.size());
  if ((mesh.nu == 1 || mesh.nv == 1) && mesh.nu * mesh.nv == n) {
    AddStrip(of_node, mesh, model);
    return;
  }
  for (int p = 0; p < n; ++p) {  // a full grid's ids run row by row: p = j*nu + i
    const Neighbours nb = NeighboursOf(lattice, mesh.grid_index[p][0], mesh.grid_index[p][1]);
    AddBending(*of_node[p], mesh, p, nb, friction_reference, model);
    AddMembrane(rigidities.at(of_node[p]), *of_node[p], cell_shear, lattice, mesh, p, nb,
                friction_reference, model);
  }
  AddTwist(of_node, lattice, mesh, model);
  if (cell_shear) AddCellShear(of_node, lattice, mesh, model);
}

}  // namespace drape
