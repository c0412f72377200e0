// The finite-volume fabric (Hu/Teng, §9.2): orthotropic membrane and bending energies of the
// control volumes of a structured grid, added to a Model as "fv_membrane" and "fv_bending" terms.
#ifndef DRAPE_SRC_FINITE_VOLUME_H_
#define DRAPE_SRC_FINITE_VOLUME_H_

#include "src/mesh.h"
#include "src/model.h"
#include "src/scene.h"

namespace drape {

// The plane-stress rigidities of eq. 9.5, N/m.
struct MembraneRigidities {
  double e1 = 0.0, e2 = 0.0, e12 = 0.0, g = 0.0;
};
MembraneRigidities PlaneStressRigidities(const FiniteVolumeSpec& spec);

// Adds the terms of `spec` for the structured grid `mesh` (Mesh::nu × Mesh::nv nodes, id
// j*nu + i, possibly non-uniform spacing) to `model`, whose nodes are the mesh's nodes. The rest
// state is the mesh itself (flat, orthogonal grid); node masses are not touched (the model
// builder sets them from Mesh::area, the control-volume areas).
// - 2-D grid (nu, nv ≥ 2): per node one bending term — FvBending (W, P, E, S, N) for an internal
//   volume, FvBendingEdge along the one direction that continues for an edge volume (no
//   curvature across a free edge: its bending moment vanishes there), none at a corner — and one
//   FvMembrane per quarter section whose two arms exist (4 inside, 2 on an edge, 1 at a corner).
// - strip (nv = 1 along u, or nu = 1 along v; `dimension: 2` scenes): FvBendingEdge at every
//   node but the two ends, and per link the membrane energy ½ E ε² l w (w the strip width,
//   Mesh::area / lumped length) as a SpringStretch of stiffness E w / l. E is E_warp (E_weft for
//   a column), the modulus of a strip free to contract sideways (E1 − E12²/E2 = E_warp).
// Throws InputError at spec.where for a mesh that is not a grid with area, or rigidities whose
// energy is not positive semidefinite (ν_warp ν_weft ≥ 1, E1 E2 < E12², D12² > D_warp D_weft).
void AddFiniteVolumeTerms(const FiniteVolumeSpec& spec, const Mesh& mesh, Model* model);

}  // namespace drape

#endif  // DRAPE_SRC_FINITE_VOLUME_H_
