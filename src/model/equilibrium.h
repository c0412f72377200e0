// Energy, forces and the equilibrium certificate of a model at given positions. Every solver and
// every result uses these, so "converged" means the same thing whichever method ran.
#ifndef DRAPE_SRC_MODEL_EQUILIBRIUM_H_
#define DRAPE_SRC_MODEL_EQUILIBRIUM_H_

#include <map>
#include <string>
#include <vector>

#include "src/model/model.h"

namespace drape {

// Numbering of the free coordinates (those not prescribed), in global order.
class DofMap {
 public:
  explicit DofMap(const Model& model);
  int num_free() const { return static_cast<int>(free_to_global_.size()); }
  const std::vector<int>& free_to_global() const { return free_to_global_; }
  // -1 for a fixed coordinate.
  const std::vector<int>& global_to_free() const { return global_to_free_; }
  void Gather(const double* global, double* free) const;
  void Scatter(const double* free, double* global) const;

 private:
  std::vector<int> free_to_global_;
  std::vector<int> global_to_free_;
};

// Total energy at `positions` (3 per node); optionally its gradient over all 3n coordinates and the
// energy of each term type. False if a term is undefined there or a value is not finite.
bool EvaluateEnergy(const Model& model, const double* positions, double* energy,
                    std::vector<double>* gradient = nullptr,
                    std::map<std::string, double>* energy_by_type = nullptr);

// Norm of the weight and applied loads (the denominator of the relative residual). Where nothing
// is applied (only prescribed displacements), the norm of the support reactions is used instead.
double ReferenceForce(const Model& model, const std::vector<double>& gradient);

// ‖free residual forces‖ / ReferenceForce, from the gradient over all coordinates.
double RelativeResidual(const Model& model, const std::vector<double>& gradient);

// The proof a result carries: forces at the final positions, computed afresh.
struct Certificate {
  bool evaluable = false;  // energy and forces finite at the positions
  double energy = 0.0;     // J
  std::map<std::string, double> energy_by_type;
  double relative_residual = 0.0;   // ‖free residual forces‖ / reference force
  double max_node_force = 0.0;      // N, largest free nodal residual force (Euclidean per node)
  double reference_force = 0.0;     // N
  std::vector<double> node_forces;  // 3 per node: reaction at fixed dofs, residual at free ones
  Eigen::Vector3d reaction_sum = Eigen::Vector3d::Zero();  // N, total force of the supports
  // Contact: the force of the obstacles on each node (3 per node, −∇ of the contact terms; empty
  // without obstacles), their total, and the total per obstacle (in the scene's order), N.
  std::vector<double> contact_forces;
  Eigen::Vector3d contact_sum = Eigen::Vector3d::Zero();
  std::vector<Eigen::Vector3d> contact_sum_by_obstacle;
  // Constraint forces given to ComputeCertificate (Provot's), in total, N.
  Eigen::Vector3d constraint_sum = Eigen::Vector3d::Zero();
  // Balance of the whole fabric: |reactions + contact + constraint + weight and loads| over the
  // reference force. At equilibrium it is at most √(free nodes) × the relative residual (the free
  // residual forces are all that is left), up to rounding; `balanced` says whether it is.
  Eigen::Vector3d applied_sum = Eigen::Vector3d::Zero();  // N, weight + loads
  double balance_error = 0.0;
  bool balanced = false;
  // Why the state cannot be certified, whatever its residual (empty if it can): not finite, a node
  // inside an obstacle's body (beyond the clearance layer), or run away (a node farther than
  // kRunawayFactor × the scene's size from where the fabric started).
  std::string unsound;
};
constexpr double kRunawayFactor = 1e3;
// `constraint_forces` (3 per node, N), if given: forces that hold the fabric besides the energy's
// (Provot's stretch-limit constraint); they count in the residual and the reactions.
Certificate ComputeCertificate(const Model& model, const double* positions,
                               const std::vector<double>* constraint_forces = nullptr);

}  // namespace drape

#endif  // DRAPE_SRC_MODEL_EQUILIBRIUM_H_
