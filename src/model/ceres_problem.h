// The model as a ceres::Problem: a parameter block of 3 doubles per node (pointing into
// model.positions), one residual block per term, fully fixed nodes constant, partly fixed nodes
// on a SubsetManifold.
#ifndef DRAPE_SRC_MODEL_CERES_PROBLEM_H_
#define DRAPE_SRC_MODEL_CERES_PROBLEM_H_

#include <ceres/problem.h>

#include "src/model/model.h"

namespace drape {

// Validates the model, then adds it to `problem` (which must be empty).
void BuildProblem(Model& model, ceres::Problem* problem);

}  // namespace drape

#endif  // DRAPE_SRC_MODEL_CERES_PROBLEM_H_
