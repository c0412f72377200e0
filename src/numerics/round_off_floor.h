// The round-off floor of the equilibrium residual: how small double precision can make the
// relative residual at given positions, so that a tolerance below it is recognised as one that
// cannot be certified (instead of iterating in place until a limit).
//
// Two sources, per free coordinate i:
//  - the sum of the terms' forces at the node cancels at equilibrium, each carrying a relative
//    rounding of ε: ε Σ_terms |∂E_t/∂x_i|;
//  - the positions themselves are doubles: the nearest representable state is off the exact one
//    by up to half an ulp per coordinate, ε|x_j|/2, which changes the forces by H δ; with
//    independent roundings, √(Σ_j H_ij² (ε|x_j|/2)²) (H the free Hessian). This is the floor of a
//    long stiff structure far from the origin (a 325 m cable of 8e6 N/m springs: ~1e-8).
// The floor is the norm of their sum over the free coordinates, over the reference force.
#ifndef DRAPE_SRC_NUMERICS_ROUND_OFF_FLOOR_H_
#define DRAPE_SRC_NUMERICS_ROUND_OFF_FLOOR_H_

#include <memory>

#include "src/model/equilibrium.h"
#include "src/model/model.h"
#include "src/numerics/sparse_hessian.h"

namespace drape {

// The relative residual's round-off floor at `positions` (see above); 0 when the model has no
// free coordinate, +∞ when the forces or the Hessian are not finite there.
// `hessian`, when given, is a FreeHessian of `model` to assemble in (its values are overwritten).
double RelativeResidualFloor(const Model& model, const double* positions,
                             FreeHessian* hessian = nullptr);

// The same at successive positions of one model (a solver's stagnation checks): the free Hessian's
// pattern and scatter map, most of one estimate's cost (three quarters on the 2,821-node drape
// tester, docs/benchmarks.md, session 15), are built at the first estimate and kept; or, when
// `hessian` is given, that FreeHessian of the model is used (its values are overwritten). Its own
// is built again where the model's terms have changed (FreeHessian::Stale).
class ResidualFloorEstimator {
 public:
  explicit ResidualFloorEstimator(const Model& model, FreeHessian* hessian = nullptr)
      : model_(model), hessian_(hessian) {}
  double At(const double* positions);

 private:
  const Model& model_;
  FreeHessian* hessian_;                    // the given one, else own_hessian_ once built
  std::unique_ptr<const DofMap> own_dofs_;  // both built at the first At() without a given one
  std::unique_ptr<FreeHessian> own_hessian_;
};

// A residual within this factor of the floor is at the floor (the estimate is of its order).
constexpr double kFloorFactor = 2.0;

}  // namespace drape

#endif  // DRAPE_SRC_NUMERICS_ROUND_OFF_FLOOR_H_
