#include "src/model/ceres_problem.h"

#include <ceres/manifold.h>

#include <vector>

namespace drape {

void BuildProblem(Model& model, ceres::Problem* problem) {
  ValidateModel(model);
  for (int node = 0; node < model.num_nodes; ++node) {
    double* block = model.positions.data() + 3 * node;
    problem->AddParameterBlock(block, 3);
    std::vector<int> constant;
    for (int c = 0; c < 3; ++c) {
      if (model.fixed[3 * node + c]) constant.push_back(c);
    }
    if (constant.size() == 3) {
      problem->SetParameterBlockConstant(block);
    } else if (!constant.empty()) {
      problem->SetManifold(block, new ceres::SubsetManifold(3, constant));
    }
  }
  std::vector<double*> blocks;
  for (const auto& term : model.terms) {
    blocks.clear();
    for (int node : term->nodes()) blocks.push_back(model.positions.data() + 3 * node);
    problem->AddResidualBlock(term->NewCostFunction(), nullptr, blocks);
  }
}

}  // namespace drape
