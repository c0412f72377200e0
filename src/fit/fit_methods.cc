#include "src/fit/fit_methods.h"

namespace drape {

const std::vector<FitMethod>& FitMethodTable() {
  using Engine = FitMethod::Engine;
  static const std::vector<FitMethod> table = {
      {"bobyqa", Engine::kNlopt, nlopt::LN_BOBYQA, false},
      {"nelder-mead", Engine::kNlopt, nlopt::LN_NELDERMEAD, false},
      {"sbplx", Engine::kNlopt, nlopt::LN_SBPLX, false},
      {"cobyla", Engine::kNlopt, nlopt::LN_COBYLA, false},
      {"implicit-lbfgs", Engine::kNlopt, nlopt::LD_LBFGS, true},
      {"implicit-lm", Engine::kCeresLevenbergMarquardt, nlopt::LN_BOBYQA, true},
  };
  return table;
}

const FitMethod* FindFitMethod(const std::string& name) {
  for (const FitMethod& method : FitMethodTable()) {
    if (method.name == name) return &method;
  }
  return nullptr;
}

const std::vector<std::string>& FitMethods() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> list;
    for (const FitMethod& method : FitMethodTable()) list.push_back(method.name);
    return list;
  }();
  return names;
}

std::string FitMethodList() {
  std::string list;
  for (const std::string& name : FitMethods()) list += (list.empty() ? "" : ", ") + name;
  return list;
}

}  // namespace drape
