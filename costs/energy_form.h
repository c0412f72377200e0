// How a cost functor's outputs make an energy (see src/model/term.h).
#ifndef DRAPE_COSTS_ENERGY_FORM_H_
#define DRAPE_COSTS_ENERGY_FORM_H_

#include "costs/nested_jet.h"

namespace drape {

enum class EnergyForm {
  kSquares,    // outputs are residuals r, energy ½|r|² (Ceres' convention)
  kPotential,  // output[0] is the energy itself
};

}  // namespace drape

#endif  // DRAPE_COSTS_ENERGY_FORM_H_
