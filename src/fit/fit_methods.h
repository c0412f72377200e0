// The fit methods: the one table of their names and what runs each. Read by the fit file's
// `method:` key (src/fit/fit_file.cc), `drape fit --method` and its help text (src/cli/cli.cc),
// and the outer loop's dispatch (src/fit/fit_solver.cc). Adding a method is one row here (and the
// code that runs it, if it is not an NLopt algorithm).
#ifndef DRAPE_SRC_FIT_FIT_METHODS_H_
#define DRAPE_SRC_FIT_FIT_METHODS_H_

#include <nlopt.hpp>
#include <string>
#include <vector>

namespace drape {

struct FitMethod {
  enum class Engine { kNlopt, kCeresLevenbergMarquardt };
  std::string name;
  Engine engine = Engine::kNlopt;
  nlopt::algorithm algorithm = nlopt::LN_BOBYQA;  // for Engine::kNlopt
  bool implicit = false;  // uses the implicit derivatives dx*/dθ (a gradient or a Jacobian)
};

// In the order the help text lists them; the first is the default.
const std::vector<FitMethod>& FitMethodTable();

// The row named `name`, or nullptr.
const FitMethod* FindFitMethod(const std::string& name);

// The names, in table order.
const std::vector<std::string>& FitMethods();

// "bobyqa, nelder-mead, ...": the names for messages.
std::string FitMethodList();

}  // namespace drape

#endif  // DRAPE_SRC_FIT_FIT_METHODS_H_
