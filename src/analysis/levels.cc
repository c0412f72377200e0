#include "src/analysis/levels.h"

#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <cstdio>
#include <map>
#include <set>
#include <string>
#include <utility>

#include "src/analysis/drape_analysis.h"
#include "src/analysis/mesh_rule.h"
#include "src/model/contact.h"
#include "src/model/mesh.h"
#include "src/scene/material_models.h"

namespace drape {

namespace {

// Lattice edges of an interpolated start are shortened to at most 1 + kStretchLimit times their
// rest length (LimitLatticeStretch), by at most this many passes.
constexpr double kStretchLimit = 0.01;
constexpr int kMaxStretchLimitPasses = 200;

// One axis of a lattice: node index i stands at coordinate (i − offset) h, i in [0, count).
struct Axis {
  double h = 0.0;  // 0 for a single node
  double offset = 0.0;
  int count = 1;
};

struct LatticeAxes {
  Axis u, v;
};

int CircleHalfWidth(const MeshSpec& mesh) {
  return static_cast<int>(std::floor(mesh.radius / mesh.spacing * (1.0 + 1e-9)));
}

// The axes of a mesh of nested lattices (CheckScalable, LatticeSpacing).
LatticeAxes AxesOf(const MeshSpec& mesh) {
  LatticeAxes axes;
  switch (mesh.kind) {
    case MeshSpec::Kind::kCircle: {
      const int m = CircleHalfWidth(mesh);
      axes.u = axes.v = Axis{mesh.spacing, static_cast<double>(m), 2 * m + 1};
      break;
    }
    case MeshSpec::Kind::kGrid: {
      auto axis = [](double size, int nodes) {
        return Axis{nodes > 1 ? size / (nodes - 1) : 0.0, 0.0, nodes};
      };
      axes.u = axis(mesh.size.x(), mesh.nodes[0]);
      axes.v = axis(mesh.size.y(), mesh.nodes[1]);
      break;
    }
    case MeshSpec::Kind::kArc:
    case MeshSpec::Kind::kChain:
    case MeshSpec::Kind::kFile:
      assert(false && "no lattice: CheckScalable and LatticeSpacing keep this kind out");
      break;
  }
  return axes;
}

// The coarse lattice coordinate of fine index i.
double MapIndex(double i, const Axis& fine, const Axis& coarse) {
  if (coarse.count == 1 || fine.h == 0.0) return 0.0;
  return (i - fine.offset) * fine.h / coarse.h + coarse.offset;
}

[[noreturn]] void Refuse(const Scene& scene, const std::string& what) {
  throw InputError(scene.solver.levels_where, std::to_string(scene.solver.levels) + " " + what);
}

void CheckScalable(const Scene& scene) {
  const MeshSpec& mesh = scene.mesh;
  switch (mesh.kind) {
    case MeshSpec::Kind::kGrid:
      if (!mesh.u.empty() || !mesh.v.empty()) {
        Refuse(scene, "needs a uniform grid (mesh.size and mesh.nodes, not explicit u/v)");
      }
      break;
    case MeshSpec::Kind::kCircle:
      break;
    case MeshSpec::Kind::kArc:
    case MeshSpec::Kind::kChain:
    case MeshSpec::Kind::kFile:
      Refuse(scene, "needs a grid or circle mesh (nested lattices)");
  }
  if (scene.material.mass_kind == MaterialSpec::MassKind::kNodeMass) {
    Refuse(scene, "needs the mass as density or total_mass (a mass per node changes with h)");
  }
  for (const ForceSpec& force : scene.loads.forces) {
    switch (force.kind) {
      case ForceSpec::Kind::kTotal:
      case ForceSpec::Kind::kTraction:
      case ForceSpec::Kind::kPressure:
        break;  // the same load on every lattice
      case ForceSpec::Kind::kEach:
      case ForceSpec::Kind::kValues:
      case ForceSpec::Kind::kRamp:
        Refuse(scene,
               "needs forces given as `total`, `traction` or `pressure` (a force per node changes "
               "with h)");
    }
  }
}

// The coarse mesh spec for `factor`; refused if a lattice would have fewer than 3 nodes across.
MeshSpec CoarsenedMesh(const Scene& scene, int factor) {
  MeshSpec mesh = scene.mesh;
  switch (mesh.kind) {
    case MeshSpec::Kind::kCircle:
      mesh.spacing *= factor;
      if (CircleHalfWidth(mesh) < 1) {
        Refuse(scene, "is too many for this circle: the coarsest spacing " +
                          std::to_string(mesh.spacing) + " m leaves fewer than 3 nodes across");
      }
      return mesh;
    case MeshSpec::Kind::kGrid:
      break;  // below
    case MeshSpec::Kind::kArc:
    case MeshSpec::Kind::kChain:
    case MeshSpec::Kind::kFile:
      assert(false && "no lattice: CheckScalable keeps this kind out");
      return mesh;
  }
  for (int k = 0; k < 2; ++k) {
    const int n = scene.mesh.nodes[k];
    if (n == 1) continue;
    const int coarse = static_cast<int>(std::lround(static_cast<double>(n - 1) / factor)) + 1;
    if (coarse < 3) {
      Refuse(scene, "is too many for mesh.nodes " + std::to_string(n) +
                        ": the coarsest lattice would have fewer than 3 nodes across");
    }
    mesh.nodes[k] = coarse;
  }
  return mesh;
}

// Node ids of `mesh` by lattice index (-1 where none).
class LatticeIds {
 public:
  explicit LatticeIds(const Mesh& mesh) {
    for (const auto& ij : mesh.grid_index) {
      nu_ = std::max(nu_, ij[0] + 1);
      nv_ = std::max(nv_, ij[1] + 1);
    }
    ids_.assign(static_cast<size_t>(nu_) * nv_, -1);
    for (size_t k = 0; k < mesh.grid_index.size(); ++k) {
      const auto& ij = mesh.grid_index[k];
      if (ij[0] >= 0 && ij[1] >= 0) ids_[ij[1] * nu_ + ij[0]] = static_cast<int>(k);
    }
  }
  int At(long i, long j) const {
    return (i < 0 || j < 0 || i >= nu_ || j >= nv_) ? -1 : ids_[j * nu_ + i];
  }

 private:
  int nu_ = 0, nv_ = 0;
  std::vector<int> ids_;
};

// Maps `ids` / `ij` selectors of the fine scene onto the coarse lattice.
void MapSelector(const Scene& scene, const Mesh& fine, const Mesh& coarse, const LatticeAxes& fa,
                 const LatticeAxes& ca, NodeSelector* selector) {
  if (selector->kind != NodeSelector::Kind::kIds && selector->kind != NodeSelector::Kind::kIj) {
    return;
  }
  std::vector<std::array<int, 2>> ij = selector->ij;
  if (selector->kind == NodeSelector::Kind::kIds) {
    ij.clear();
    for (int id : selector->ids) {
      if (id < 0 || id >= static_cast<int>(fine.grid_index.size())) return;  // located later
      ij.push_back(fine.grid_index[id]);
    }
  }
  const LatticeIds coarse_ids(coarse);
  std::set<int> ids;
  std::set<std::array<int, 2>> coarse_ij;
  for (const auto& [i, j] : ij) {
    const double u = MapIndex(i, fa.u, ca.u), v = MapIndex(j, fa.v, ca.v);
    int found = 0;
    for (double ci : {std::floor(u), std::ceil(u)}) {
      for (double cj : {std::floor(v), std::ceil(v)}) {
        const int id = coarse_ids.At(static_cast<long>(ci), static_cast<long>(cj));
        if (id < 0) continue;
        ids.insert(id);
        coarse_ij.insert({static_cast<int>(ci), static_cast<int>(cj)});
        ++found;
      }
    }
    if (found == 0) {
      Refuse(scene, "cannot map the selected node (" + std::to_string(i) + ", " +
                        std::to_string(j) + ") onto a coarser lattice");
    }
  }
  selector->ids.assign(ids.begin(), ids.end());
  selector->ij.assign(coarse_ij.begin(), coarse_ij.end());
}

// Bilinear interpolation over a lattice of positions with a margin, filled beyond the outline.
class FilledLattice {
 public:
  static constexpr int kMargin = 3;

  FilledLattice(const Model& model, const Axis& u, const Axis& v)
      : nu_(u.count + 2 * kMargin), nv_(v.count + 2 * kMargin) {
    values_.assign(static_cast<size_t>(nu_) * nv_, Eigen::Vector3d::Zero());
    present_.assign(values_.size(), 0);
    for (int k = 0; k < model.num_nodes; ++k) {
      const auto& ij = model.grid_index[k];
      const int cell = Cell(ij[0] + kMargin, ij[1] + kMargin);
      values_[cell] = Eigen::Vector3d(model.positions.data() + 3 * k);
      present_[cell] = 1;
    }
    for (int pass = 0; pass < 2 * kMargin; ++pass) Fill();
  }

  // Position at lattice coordinate (x, y); false where the lattice has nothing there.
  bool Interpolate(double x, double y, Eigen::Vector3d* position) const {
    x += kMargin, y += kMargin;
    const int i = std::clamp(static_cast<int>(std::floor(x)), 0, nu_ - 2);
    const int j = std::clamp(static_cast<int>(std::floor(y)), 0, nv_ - 2);
    const double fx = std::clamp(x - i, 0.0, 1.0), fy = std::clamp(y - j, 0.0, 1.0);
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    double weight = 0.0;
    for (int dj = 0; dj < 2; ++dj) {
      for (int di = 0; di < 2; ++di) {
        const double w = (di ? fx : 1.0 - fx) * (dj ? fy : 1.0 - fy);
        const int cell = Cell(i + di, j + dj);
        if (w > 0.0 && present_[cell]) sum += w * values_[cell], weight += w;
      }
    }
    if (!(weight > 1e-12)) return false;
    *position = sum / weight;
    return true;
  }

 private:
  int Cell(int i, int j) const { return j * nu_ + i; }
  bool Present(int i, int j) const {
    return i >= 0 && j >= 0 && i < nu_ && j < nv_ && present_[Cell(i, j)];
  }

  // One ring outward: each missing cell next to present ones takes the mean of the linear
  // extrapolations along the lattice lines that reach it (or of its neighbours' values).
  void Fill() {
    std::vector<Eigen::Vector3d> values = values_;
    std::vector<char> present = present_;
    for (int j = 0; j < nv_; ++j) {
      for (int i = 0; i < nu_; ++i) {
        if (present_[Cell(i, j)]) continue;
        Eigen::Vector3d linear = Eigen::Vector3d::Zero(), nearest = Eigen::Vector3d::Zero();
        int linear_count = 0, nearest_count = 0;
        for (const auto& [di, dj] : {std::pair{1, 0}, {-1, 0}, {0, 1}, {0, -1}}) {
          if (!Present(i + di, j + dj)) continue;
          const Eigen::Vector3d& one = values_[Cell(i + di, j + dj)];
          nearest += one, ++nearest_count;
          if (Present(i + 2 * di, j + 2 * dj)) {
            linear += 2.0 * one - values_[Cell(i + 2 * di, j + 2 * dj)], ++linear_count;
          }
        }
        if (nearest_count == 0) continue;
        values[Cell(i, j)] = linear_count ? linear / linear_count : nearest / nearest_count;
        present[Cell(i, j)] = 1;
      }
    }
    values_.swap(values);
    present_.swap(present);
  }

  int nu_, nv_;
  std::vector<Eigen::Vector3d> values_;
  std::vector<char> present_;
};

// The root of (h1^p − h2^p)/(h2^p − h3^p) = ratio in p ∈ [0.1, 8], or NaN.
double ObservedOrder(double h1, double h2, double h3, double ratio) {
  auto f = [&](double p) {
    return (std::pow(h1, p) - std::pow(h2, p)) / (std::pow(h2, p) - std::pow(h3, p)) - ratio;
  };
  double low = 0.1, high = 8.0;
  if (f(low) > 0.0 || f(high) < 0.0) return NAN;
  for (int k = 0; k < 200; ++k) {
    const double mid = 0.5 * (low + high);
    (f(mid) < 0.0 ? low : high) = mid;
  }
  return 0.5 * (low + high);
}

std::string Joined(const std::vector<int>& values) {
  std::string text;
  for (int v : values) text += (text.empty() ? "" : ", ") + std::to_string(v);
  return text;
}

// The reason no extrapolation is made through levels whose coarsest is coarser than the fabric's
// bending length, or nothing where none is (or no bending length is known).
std::optional<std::string> CoarserThanTheFabric(const std::vector<LevelRecord>& levels,
                                                std::optional<double> bending_length) {
  const double coarsest = levels[levels.size() - 3].spacing;
  if (!bending_length || !(coarsest > *bending_length)) return std::nullopt;
  return "not in the asymptotic range: the " + LengthText(coarsest, 3) +
         " level is coarser than the fabric's bending length (" + LengthText(*bending_length, 2) +
         ") and resolves no fold";
}

void AddExtrapolations(const std::vector<LevelRecord>& levels, std::optional<double> bending_length,
                       LevelsReport* report) {
  std::vector<double> spacing, energy, dc;
  std::vector<int> folds;
  bool all_converged = true, all_dc = true, any_passes_through = false;
  for (const LevelRecord& level : levels) {
    spacing.push_back(level.spacing);
    energy.push_back(level.energy);
    all_converged = all_converged && level.converged;
    any_passes_through = any_passes_through || level.PassesThrough();
    all_dc = all_dc && level.drape_coefficient.has_value();
    if (level.drape_coefficient) dc.push_back(*level.drape_coefficient);
    if (level.folds) folds.push_back(*level.folds);
  }
  std::vector<std::pair<std::string, std::vector<double>>> quantities;
  if (all_dc) quantities.emplace_back("drape_coefficient", dc);
  quantities.emplace_back("energy", energy);
  const int n = static_cast<int>(levels.size());
  const std::vector<int> last_folds(folds.size() >= 3 ? folds.end() - 3 : folds.begin(),
                                    folds.end());
  const bool folds_differ =
      last_folds.size() >= 2 && std::any_of(last_folds.begin(), last_folds.end(),
                                            [&](int count) { return count != last_folds.front(); });
  for (const auto& [name, values] : quantities) {
    Extrapolation e;
    e.quantity = name;
    if (n < 3) {
      e.reason = "needs 3 levels (solver.levels: 3 or more)";
    } else if (!all_converged) {
      e.reason = "a level did not converge";
    } else if (any_passes_through) {
      e.reason =
          "the fabric passes through the support disk or through itself on a level "
          "(edges_through_disk, self_crossings)";
    } else if (folds_differ) {
      e.reason = "the fold count differs between the finest levels (" + Joined(last_folds) +
                 "): different fold patterns, not one converging answer";
    } else {
      e = Extrapolate(name, spacing, values);
      if (const std::optional<std::string> coarse = CoarserThanTheFabric(levels, bending_length);
          e.available && coarse) {
        e = Extrapolation();
        e.quantity = name;
        e.reason = *coarse;
      }
    }
    report->extrapolations.push_back(e);
  }
}

// The disc's contact acts from both sides, so an interpolated node that lands in the disc's
// contact layer below its mid-plane, over a part where the coarse surface lay on its top, would
// be pushed down through it; one that lands within the clearance of the rim starts deep in its
// contact. Such nodes are moved out to the disc's clearance, the nearest point where its contact
// (costs/disk_contact.h) is zero on the side it started: up over the disc, out from the rim
// beside it. Nodes below the layer stay where the coarse surface put them: the coarse level had
// no edge through the disc (else this level starts flat), so they hang under it round its rim.
void KeepOnDiscs(const Scene& scene, Model* model) {
  const double clearance = scene.contact.thickness;
  for (const ObstacleSpec& disc : scene.obstacles) {
    if (disc.kind != "disk") continue;
    for (int k = 0; k < model->num_nodes; ++k) {
      double* x = model->positions.data() + 3 * k;
      if (!(model->initial[3 * k + 2] > disc.center.z())) continue;
      if (model->fixed[3 * k] || model->fixed[3 * k + 1] || model->fixed[3 * k + 2]) continue;
      const DiscPlace place = PlaceOnDisc(disc, clearance, x);
      if (place == DiscPlace::kInLayer) {  // over the disc: back on its top
        x[2] = disc.center.z() + clearance;
        continue;
      }
      const double dx = x[0] - disc.center.x(), dy = x[1] - disc.center.y();
      const double h = x[2] - disc.center.z(), rho = std::hypot(dx, dy);
      const double beyond = rho - disc.radius, distance = std::hypot(beyond, h);
      if (!(beyond > 0.0) || !(distance < clearance)) continue;
      const double scale = (clearance / distance - 1.0) * beyond / rho;
      x[0] += scale * dx, x[1] += scale * dy;
      x[2] = disc.center.z() + h * clearance / distance;
    }
  }
}

// The lattice edges of a model (sides and diagonals), as node pairs.
std::vector<std::array<int, 2>> LatticeEdges(const Model& model) {
  std::map<std::array<int, 2>, int> node_at;
  for (int k = 0; k < model.num_nodes; ++k) node_at[model.grid_index[k]] = k;
  std::vector<std::array<int, 2>> edges;
  for (const auto& [ij, k] : node_at) {
    for (const auto& [di, dj] : {std::pair{1, 0}, {0, 1}, {1, 1}, {1, -1}}) {
      const auto other = node_at.find({ij[0] + di, ij[1] + dj});
      if (other != node_at.end()) edges.push_back({k, other->second});
    }
  }
  return edges;
}

// Moves the free ends of one lattice edge a → b so that it is stretched by at most kStretchLimit
// (the fixed end stays; two free ends share the move). Returns the relative excess it had.
double LimitEdgeStretch(const std::array<int, 2>& edge, Model* model) {
  const auto [a, b] = edge;
  double* x = model->positions.data();
  const double* x0 = model->initial.data();
  const Eigen::Vector3d d = Eigen::Vector3d(x + 3 * b) - Eigen::Vector3d(x + 3 * a);
  const double rest = (Eigen::Vector3d(x0 + 3 * b) - Eigen::Vector3d(x0 + 3 * a)).norm();
  const double length = d.norm();
  if (!(length > 0.0) || !(rest > 0.0)) return 0.0;
  const double target = std::min(length, (1.0 + kStretchLimit) * rest);
  if (target == length) return 0.0;
  const Eigen::Vector3d gap = (length - target) / length * d;
  for (int c = 0; c < 3; ++c) {
    const bool free_a = !model->fixed[3 * a + c], free_b = !model->fixed[3 * b + c];
    const double share = free_a && free_b ? 0.5 : 1.0;
    if (free_a) x[3 * a + c] += share * gap[c];
    if (free_b) x[3 * b + c] -= share * gap[c];
  }
  return std::abs(length - target) / rest;
}

// Bilinear interpolation keeps a coarse lattice's lengths except where the fabric bends sharply
// between two coarse nodes (over a disc's rim): there KeepOnDiscs lifts the nodes inside the rim
// and the lattice edges beside them are stretched by up to 100 %, a membrane energy 10³–10⁴× the
// drape's (the 5 mm drape tester interpolated from 1 cm: 0.34 J against 6e-5 J), which newton
// then spends its first iterations undoing. Gauss–Seidel passes of stretch limiting (Provot's
// projection) over the lattice edges, the discs kept after each pass, shorten every edge to at
// most 1 + kStretchLimit times its rest length; edges within it, as in a smooth drape, are not
// moved. Compressed edges are left: a coarse lattice's compression stands for folds finer than it
// (limiting it too did not converge: 3 % left after 200 passes on the 2 cm drape tester).
void LimitLatticeStretch(const Scene& scene, Model* model) {
  const std::vector<std::array<int, 2>> edges = LatticeEdges(*model);
  for (int pass = 0; pass < kMaxStretchLimitPasses; ++pass) {
    double worst = 0.0;
    for (const auto& edge : edges) worst = std::max(worst, LimitEdgeStretch(edge, model));
    KeepOnDiscs(scene, model);
    if (worst < 0.1 * kStretchLimit) return;
  }
}

}  // namespace

Scene CoarsenedScene(const Scene& scene, int factor) {
  if (factor == 1) return scene;
  CheckScalable(scene);
  Scene coarse = scene;
  coarse.mesh = CoarsenedMesh(scene, factor);
  const LatticeAxes fine_axes = AxesOf(scene.mesh), coarse_axes = AxesOf(coarse.mesh);
  const double ratio =
      coarse_axes.u.h > 0.0 ? coarse_axes.u.h / fine_axes.u.h : coarse_axes.v.h / fine_axes.v.h;
  const MaterialModelRow& model = MaterialModelOf(scene.material.model);
  assert(model.rescale_for_spacing && "a material model without its rescaling rule");
  model.rescale_for_spacing(ratio, &coarse.material);
  const Mesh fine_mesh = BuildMesh(scene.mesh), coarse_mesh = BuildMesh(coarse.mesh);
  for (FixedSpec& fixed : coarse.fixed) {
    MapSelector(scene, fine_mesh, coarse_mesh, fine_axes, coarse_axes, &fixed.nodes);
  }
  for (ForceSpec& force : coarse.loads.forces) {
    MapSelector(scene, fine_mesh, coarse_mesh, fine_axes, coarse_axes, &force.nodes);
  }
  return coarse;
}

void ProlongPositions(const Scene& coarse_scene, const Model& coarse, const Scene& fine_scene,
                      Model* fine) {
  const LatticeAxes ca = AxesOf(coarse_scene.mesh), fa = AxesOf(fine_scene.mesh);
  const FilledLattice lattice(coarse, ca.u, ca.v);
  for (int k = 0; k < fine->num_nodes; ++k) {
    const auto& ij = fine->grid_index[k];
    Eigen::Vector3d position;
    if (!lattice.Interpolate(MapIndex(ij[0], fa.u, ca.u), MapIndex(ij[1], fa.v, ca.v), &position)) {
      continue;
    }
    for (int c = 0; c < 3; ++c) {
      if (!fine->fixed[3 * k + c]) fine->positions[3 * k + c] = position[c];
    }
  }
  KeepOnDiscs(fine_scene, fine);
  LimitLatticeStretch(fine_scene, fine);
}

Extrapolation Extrapolate(const std::string& quantity, const std::vector<double>& spacing,
                          const std::vector<double>& values) {
  Extrapolation e;
  e.quantity = quantity;
  const int n = static_cast<int>(values.size());
  if (n < 3 || spacing.size() != values.size()) {
    e.reason = "needs 3 levels";
    return e;
  }
  const double h1 = spacing[n - 3], h2 = spacing[n - 2], h3 = spacing[n - 1];
  const double q1 = values[n - 3], q2 = values[n - 2], q3 = values[n - 1];
  const double d1 = q1 - q2, d2 = q2 - q3;
  if (d2 == 0.0 || d1 * d2 <= 0.0) {
    e.reason = "not in the asymptotic range: the change between levels does not shrink steadily";
    return e;
  }
  const double order = ObservedOrder(h1, h2, h3, d1 / d2);
  if (!std::isfinite(order)) {
    e.reason = "not in the asymptotic range: observed order outside [0.1, 8]";
    return e;
  }
  const double c = d2 / (std::pow(h2, order) - std::pow(h3, order));
  e.available = true;
  e.observed_order = order;
  e.value = q3 - c * std::pow(h3, order);
  e.error_estimate = std::abs(q3 - e.value);
  return e;
}

double LevelSpacing(const MeshSpec& mesh) {
  const LatticeAxes axes = AxesOf(mesh);
  return axes.u.h > 0.0 ? axes.u.h : axes.v.h;
}

void AnalyseLevels(LevelsReport* report, std::optional<double> bending_length) {
  report->extrapolations.clear();
  AddExtrapolations(report->levels, bending_length, report);
  report->drape_error = DrapeErrorOf(report->levels, report->extrapolations);
}

std::string LengthText(double metres, int cm_digits) {
  char text[32];
  if (metres >= 0.01) {
    std::snprintf(text, sizeof text, "%.*g cm", cm_digits, 100.0 * metres);
  } else {
    std::snprintf(text, sizeof text, "%.2g mm", 1000.0 * metres);
  }
  return text;
}

double LatticeSpacing(const MeshSpec& mesh) {
  switch (mesh.kind) {
    case MeshSpec::Kind::kGrid:
      return mesh.u.empty() ? AxesOf(mesh).u.h : 0.0;  // 0: not uniform
    case MeshSpec::Kind::kCircle:
      return AxesOf(mesh).u.h;
    case MeshSpec::Kind::kArc:
    case MeshSpec::Kind::kChain:
    case MeshSpec::Kind::kFile:
      return 0.0;
  }
  return 0.0;
}

std::optional<DrapeErrorBar> DrapeErrorOf(const std::vector<LevelRecord>& levels,
                                          const std::vector<Extrapolation>& extrapolations) {
  const int n = static_cast<int>(levels.size());
  if (n < 2) return std::nullopt;
  const LevelRecord &fine = levels[n - 1], &coarser = levels[n - 2];
  for (const LevelRecord* level : {&fine, &coarser}) {
    if (!level->drape_coefficient || !level->converged || level->PassesThrough()) {
      return std::nullopt;
    }
  }
  DrapeErrorBar bar;
  bar.value = *fine.drape_coefficient;
  for (const LevelRecord& level : levels) bar.folds.push_back(level.folds.value_or(0));
  bar.folds_differ = bar.folds[n - 1] != bar.folds[n - 2];
  for (const Extrapolation& e : extrapolations) {
    if (e.quantity != "drape_coefficient" || !e.available) continue;
    bar.levels_error = e.error_estimate;
    char basis[64];
    std::snprintf(basis, sizeof basis, "Richardson, observed order %.2f", e.observed_order);
    bar.levels_basis = basis;
    break;
  }
  if (bar.levels_basis.empty()) {
    bar.levels_error = std::abs(bar.value - *coarser.drape_coefficient);
    bar.levels_basis = "change from the " + LengthText(coarser.spacing, 3) + " level";
  }
  return bar;
}

double DrapeErrorBar::error() const { return MeshRuleIsLarger() ? *mesh_rule_error : levels_error; }

std::string DrapeErrorBar::basis() const {
  if (!MeshRuleIsLarger()) return levels_basis;
  char levels[24];
  std::snprintf(levels, sizeof levels, " %.2g", levels_error);
  return MeshRuleBasis(mesh_rule_bending_length) + "; " + levels_basis + levels;
}

}  // namespace drape
