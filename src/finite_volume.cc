#include "src/finite_volume.h"

#include <cmath>
#include <string>
#include <vector>

#include "costs/fv_bending.h"
#include "costs/fv_membrane.h"
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
}

void CheckGrid(const FiniteVolumeSpec& spec, const Mesh& mesh, const Model& model) {
  const int n = static_cast<int>(mesh.nodes.size());
  const bool grid = mesh.nu > 0 && mesh.nv > 0 && mesh.nu * mesh.nv == n &&
                    static_cast<int>(mesh.area.size()) == n && model.num_nodes == n;
  bool has_area = grid;
  for (int k = 0; grid && k < n; ++k) has_area = has_area && mesh.area[k] > 0.0;
  if (!grid || !has_area) {
    throw InputError(spec.where,
                     "the finite_volume material needs a grid mesh with area (mesh.kind: grid; "
                     "a 2-D strip is a grid with nodes: [n, 1] and size: [length, width])");
  }
}

double RestDistance(const Mesh& mesh, int a, int b) {
  return (mesh.nodes[b] - mesh.nodes[a]).norm();
}

// A single row (or column) of nodes: a strip bending in one direction.
void AddStrip(const FiniteVolumeSpec& spec, const Mesh& mesh, Model* model) {
  const bool row = mesh.nv == 1;
  const int count = row ? mesh.nu : mesh.nv;
  const int step = row ? 1 : mesh.nu;
  const double modulus = row ? spec.E_warp : spec.E_weft;
  const double rigidity = row ? spec.D_warp : spec.D_weft;
  std::vector<double> size(count, 0.0);  // lumped length of each control volume
  for (int k = 0; k + 1 < count; ++k) {
    const double half = 0.5 * RestDistance(mesh, k * step, (k + 1) * step);
    size[k] += half;
    size[k + 1] += half;
  }
  for (int k = 0; k + 1 < count; ++k) {
    const int a = k * step, b = (k + 1) * step;
    const double length = RestDistance(mesh, a, b);
    const double area = 0.5 * length * (mesh.area[a] / size[k] + mesh.area[b] / size[k + 1]);
    model->terms.push_back(MakeTerm(
        "fv_membrane", {a, b}, SpringStretch::Create(modulus * area / (length * length), length)));
  }
  if (!(rigidity > 0.0)) return;
  for (int k = 1; k + 1 < count; ++k) {
    const int a = (k - 1) * step, p = k * step, b = (k + 1) * step;
    model->terms.push_back(
        MakeTerm("fv_bending", {a, p, b}, FvBendingEdge::Create(rigidity, size[k], mesh.area[p])));
  }
}

// Neighbour ids of node (i, j), -1 beyond the edge.
struct Neighbours {
  int w, e, s, n;
};

Neighbours NeighboursOf(const Mesh& mesh, int i, int j) {
  const int id = j * mesh.nu + i;
  return {i > 0 ? id - 1 : -1, i + 1 < mesh.nu ? id + 1 : -1, j > 0 ? id - mesh.nu : -1,
          j + 1 < mesh.nv ? id + mesh.nu : -1};
}

void AddBending(const FiniteVolumeSpec& spec, const Mesh& mesh, int p, const Neighbours& nb,
                Model* model) {
  const bool warp = nb.w >= 0 && nb.e >= 0, weft = nb.s >= 0 && nb.n >= 0;
  const double area = mesh.area[p];
  const double size1 = warp ? 0.5 * (RestDistance(mesh, nb.w, p) + RestDistance(mesh, p, nb.e)) : 0;
  const double size2 = weft ? 0.5 * (RestDistance(mesh, nb.s, p) + RestDistance(mesh, p, nb.n)) : 0;
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

void AddMembrane(const MembraneRigidities& e, const Mesh& mesh, int p, const Neighbours& nb,
                 Model* model) {
  for (int a : {nb.e, nb.w}) {
    for (int b : {nb.n, nb.s}) {
      if (a < 0 || b < 0) continue;
      model->terms.push_back(
          MakeTerm("fv_membrane", {p, a, b},
                   FvMembrane::Create(e.e1, e.e2, e.e12, e.g, RestDistance(mesh, p, a),
                                      RestDistance(mesh, p, b))));
    }
  }
}

}  // namespace

void AddFiniteVolumeTerms(const FiniteVolumeSpec& spec, const Mesh& mesh, Model* model) {
  CheckMaterial(spec);
  CheckGrid(spec, mesh, *model);
  if (mesh.nu == 1 || mesh.nv == 1) {
    AddStrip(spec, mesh, model);
    return;
  }
  const MembraneRigidities rigidities = PlaneStressRigidities(spec);
  for (int j = 0; j < mesh.nv; ++j) {
    for (int i = 0; i < mesh.nu; ++i) {
      const int p = j * mesh.nu + i;
      const Neighbours nb = NeighboursOf(mesh, i, j);
      AddBending(spec, mesh, p, nb, model);
      AddMembrane(rigidities, mesh, p, nb, model);
    }
  }
}

}  // namespace drape
