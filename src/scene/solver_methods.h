// The solver methods a scene may name, and their options: the one list of names, descriptions,
// option keys, defaults, ranges and documentation. The scene loader checks `solver.method` and
// `solver.<method>.<key>` against it; the solvers read their defaults from it; `drape solvers`
// prints it; docs/reference.md's option table is checked against it (tests/solver_methods_test.cc).
// The code of each method is registered under the same name in src/solvers/solver_registry.cc.
#ifndef DRAPE_SRC_SCENE_SOLVER_METHODS_H_
#define DRAPE_SRC_SCENE_SOLVER_METHODS_H_

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "src/scene/scene.h"

namespace drape {

struct MethodOption {
  std::string key;  // solver.<method>.<key>
  // The default; none when the solver derives it from the model or the scene (default_text).
  std::optional<double> default_value;
  std::string default_text;  // the default in words, when default_value is empty
  double min = 0.0;          // the accepted range: min <= value <= max (or < where exclusive)
  double max = 0.0;
  bool min_exclusive = false;
  bool max_exclusive = false;
  bool integer = false;
  bool zero_means_none = false;  // 0 is accepted as well, outside the range ("none")
  std::string doc;               // one line
};

struct SolverMethod {
  std::string name;
  std::string description;  // one line, for `drape solvers`
  int max_iterations;       // the default solver.max_iterations for this method
  double time_limit;        // the default solver.time_limit for this method, s
  std::vector<MethodOption> options;
  // Records a per-step trace (SolverSummary::trace_columns), written as TraceFileName(name) with
  // the output kinds `history` or `kinetic` (src/scene/output_kinds.h).
  bool records_trace = false;
};

const std::vector<SolverMethod>& SolverMethods();
const SolverMethod* FindSolverMethod(const std::string& name);
const MethodOption* FindMethodOption(const SolverMethod& method, const std::string& key);

// An empty string if `value` is a valid value of `option`, else what is wrong ("must be an
// integer", "must be at least 1, got -5").
std::string CheckMethodOption(const MethodOption& option, double value);

// The range in words: "integer in [1, 1000]", "in (0, 2]", "≥ 0", "0 (none) or in (1, ∞)".
std::string DescribeRange(const MethodOption& option);
// The default in words: "20", "∞", or default_text.
std::string DescribeDefault(const MethodOption& option);

// Option `key` of `method`: the value given (solver.<method>.<key>), else its registered default
// (none if the solver derives it). `key` must be one of the method's options (asserted).
std::optional<double> MethodOptionValue(const std::string& method,
                                        const std::map<std::string, double>& given,
                                        const std::string& key);

// solver.max_iterations and solver.time_limit for a run of `method`: as given in the scene, else
// the method's defaults. `method` must be in the catalogue (asserted).
int EffectiveMaxIterations(const SolverSpec& spec, const std::string& method);
double EffectiveTimeLimit(const SolverSpec& spec, const std::string& method);

}  // namespace drape

#endif  // DRAPE_SRC_SCENE_SOLVER_METHODS_H_
