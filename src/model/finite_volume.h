// The finite-volume fabric (Hu/Teng, §9.2): orthotropic membrane and bending energies of the
// control volumes of a structured grid or circle, added to a Model as "fv_membrane" and
// "fv_bending" terms.
#ifndef DRAPE_SRC_MODEL_FINITE_VOLUME_H_
#define DRAPE_SRC_MODEL_FINITE_VOLUME_H_

#include <vector>

#include "src/model/mesh.h"
#include "src/model/model.h"
#include "src/scene/scene.h"

namespace drape {

// The plane-stress rigidities of eq. 9.5, N/m.
struct MembraneRigidities {
  double e1 = 0.0, e2 = 0.0, e12 = 0.0, g = 0.0;
};
MembraneRigidities PlaneStressRigidities(const FiniteVolumeSpec& spec);

// Adds the terms of `spec` for the structured mesh `mesh` to `model`, whose nodes are the mesh's
// nodes: a full grid (Mesh::nu × Mesh::nv nodes, id j*nu + i, possibly non-uniform spacing) or a
// circle (the lattice points of a square grid inside a disc). Neighbours are looked up through
// Mesh::grid_index: W/E = (i ∓ 1, j) along the warp (x), S/N = (i, j ∓ 1) along the weft (y),
// missing beyond a grid's edge or outside a circle's disc. The rest state is the mesh itself
// (flat, orthogonal lattice); node masses are not touched (the model builder sets them from
// Mesh::area, the control-volume areas, which are also the A_P of the bending energy).
// - 2-D lattice: per node one bending term — FvBending (W, P, E, S, N) where both directions
//   continue, FvBendingEdge along the one direction that continues for an edge volume (no
//   curvature across a free edge: its bending moment vanishes there), none where neither does
//   (a corner) — and one FvMembrane per quarter section whose two arms exist (4 inside, 2 on a
//   straight edge, 1 at a corner; on a circle's stepped rim whatever pairs of arms remain).
// - strip (a full grid with nv = 1 along u, or nu = 1 along v; `dimension: 2` scenes):
//   FvBendingEdge at every node but the two ends, and per link the membrane energy ½ E ε² l w
//   (w the strip width, Mesh::area / lumped length) as a SpringStretch of stiffness E w / l. E is
//   E_warp (E_weft for a column), the modulus of a strip free to contract sideways
//   (E1 − E12²/E2 = E_warp).
// Throws InputError at spec.where for a mesh that is not a grid or circle with area, or
// rigidities whose energy is not positive semidefinite (ν_warp ν_weft ≥ 1, E1 E2 < E12²,
// D12² > D_warp D_weft).
// With spec.friction_load_steps > 0 the frictions are a load step's
// (costs/fv_bending_friction_step.h, costs/fv_shear_friction.h): their kinks sit at
// `friction_reference` (3 coordinates per node), or at the flat state where it is null; such a
// bending friction needs a direction across its control volume, which a strip has not (InputError).
void AddFiniteVolumeTerms(const FiniteVolumeSpec& spec, const Mesh& mesh, Model* model,
                          const double* friction_reference = nullptr);
// The same with a material per node (regions, src/model/regions.h): each control volume takes the
// material of its own node — its bending term and its quarter sections' membrane terms; a strip
// link's membrane spring is two halves, each of its own node's modulus. Every distinct material is
// checked as above (at its own `where`).
void AddFiniteVolumeTerms(const std::vector<const FiniteVolumeSpec*>& of_node, const Mesh& mesh,
                          Model* model, const double* friction_reference = nullptr);

}  // namespace drape

#endif  // DRAPE_SRC_MODEL_FINITE_VOLUME_H_
