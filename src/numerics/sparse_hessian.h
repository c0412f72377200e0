// The Hessian of a model's energy over its free coordinates, and its Cholesky factorisation.
//
// FreeHessian assembles, term by term, the exact second derivatives that Term::EnergyHessian
// derives from the cost functors (nested Jets, or their staged chain rule), into a sparse pattern
// built once: the upper
// triangle in compressed columns, with the destination of every local entry of every term
// precomputed, so that each assembly only adds numbers. It keeps two sets of values over the
// same pattern: the true Hessian, and the Hessian whose every term is first projected to
// positive semidefinite (negative eigenvalues of the small local matrix set to zero, or to their
// magnitude: EigenvalueFilter); a term with a staged projection (the finite-volume terms:
// Term::EnergyHessianProjected, src/derivatives/fast_hessian.h) builds its semidefinite stand-in
// from its functor's stages instead, unchanged where its Hessian is semidefinite. The terms' local
// derivatives and projections are computed on several threads (std::thread: drape's OpenMP is
// switched off for CHOLMOD's sake) and summed by one thread in term order, so the values do not
// depend on the thread count. Only the active set is evaluated: a contact term none of whose points
// lies in its clearance layer at the state (Term::Touches, decided on values at every assembly)
// adds exact zeros and is skipped, so the values equal the whole set's bit for bit; most of a
// drape's edge contacts hang clear of the disc. The step limit (ObstacleSafeFraction,
// src/model/contact.h) still guards every contact against tunnelling between states. A term with
// no free coordinate (a drape's clamped centre: a third of its fabric terms) is evaluated once and
// its energy and fixed-coordinate gradient reused while the fixed positions stay as they were.
//
// SparseCholesky factorises a matrix of that pattern with CHOLMOD's supernodal Cholesky: the
// symbolic analysis (fill-reducing ordering, supernodes) once, the numeric factorisation per
// call. Used by the newton solver and by the stability certificate. The analysis orders the
// pattern both by AMD and by METIS's nested dissection and keeps the one whose factorisation
// takes fewer flops. CHOLMOD's default tries METIS only where AMD's fill is large (flops over
// nnz(L) of 500 or more); the drape lattices stay just below that (439 at 41,825 nodes), yet
// nested dissection, which suits a 2-D lattice, halves their flops there (7.8e9 → 4.1e9, nnz(L)
// 17.7M → 14.2M) and takes a third off them at 10,445 nodes (docs/benchmarks.md, "What limits
// newton").
#ifndef DRAPE_SRC_NUMERICS_SPARSE_HESSIAN_H_
#define DRAPE_SRC_NUMERICS_SPARSE_HESSIAN_H_

#include <cholmod.h>

#include <vector>

#include "src/derivatives/psd_projection.h"
#include "src/model/equilibrium.h"
#include "src/model/model.h"

namespace drape {

// The number of hardware threads (at least 1): FreeHessian's default for its assembly.
int DefaultAssemblyThreads();

class FreeHessian {
 public:
  // Builds the pattern of the model's terms over the free coordinates of `dofs`. Both must
  // outlive this object.
  FreeHessian(const Model& model, const DofMap& dofs);

  struct Assembly {
    double energy = 0.0;            // J
    double energy_magnitude = 0.0;  // Σ |term energy|, J: the scale of the energy's roundoff
    int projected_terms = 0;        // terms with a free coordinate whose local Hessian had a
                                    // negative eigenvalue
    int skipped_terms = 0;          // terms outside the active set (set_active_set)
    int reused_terms = 0;           // constant terms whose stored values were added
  };
  // Energy, gradient over all 3n coordinates (`gradient`, resized) and the Hessian values at
  // `positions`. With `project`, also the per-term projected values. False if a term is not
  // evaluable there or a value is not finite.
  bool Assemble(const double* positions, bool project, Assembly* assembly,
                std::vector<double>* gradient);

  void set_eigenvalue_filter(EigenvalueFilter filter) { filter_ = filter; }
  // Threads that compute the terms' local derivatives (default: the machine's hardware threads).
  // The results are bit-for-bit the same for every count.
  void set_threads(int threads) { threads_ = threads > 0 ? threads : 1; }
  int threads() const { return threads_; }
  // The active set (default on): a term that does not touch (Term::Touches: a contact outside its
  // clearance layer) is skipped; it would add exact zeros, so the values are bit-for-bit those of
  // the whole set. Asked of every term at every assembly: nothing is carried between states.
  void set_active_set(bool active_set) { active_set_ = active_set; }
  // Constant terms (default on): a term none of whose coordinates is free (a drape's clamped
  // centre) adds to the energy and to the fixed coordinates' gradient only, values that depend on
  // the fixed positions alone. They are evaluated at the first assembly, and again whenever a
  // fixed coordinate has changed since (compared bit for bit at every assembly); otherwise their
  // stored energies and gradients are added, in the same order: the values are bit-for-bit those
  // of evaluating every term.
  void set_reuse_constant_terms(bool reuse) {
    reuse_constant_terms_ = reuse;
    constants_stored_ = false;
  }

  // Whether the model's terms have changed since the pattern was built (the fabric's contact with
  // itself replaces its terms as the fabric moves: src/model/self_contact.h); a stale pattern
  // must not be assembled.
  bool Stale() const { return generation_ != model_.self_contact.generation; }

  int size() const { return dofs_.num_free(); }
  const DofMap& dofs() const { return dofs_; }
  int num_nonzeros() const { return static_cast<int>(rows_.size()); }
  const std::vector<int>& column_starts() const { return column_starts_; }
  const std::vector<int>& rows() const { return rows_; }
  // Index of each free coordinate's diagonal entry in the value arrays.
  const std::vector<int>& diagonal() const { return diagonal_; }
  const std::vector<double>& values() const { return values_; }
  const std::vector<double>& projected_values() const { return projected_; }

  // y = A x for the symmetric matrix whose upper triangle is `values` (free coordinates).
  void Multiply(const std::vector<double>& values, const double* x, double* y) const;

 private:
  void BuildPattern();
  void BuildDestinations();
  void EvaluateBlockTerm(const double* positions, bool project, bool reuse, int first, int i);
  void AddBlockTerm(int first, int i, bool project, Assembly* assembly,
                    std::vector<double>* gradient);
  void FindConstantTerms();
  bool FixedPositionsAsStored(const double* positions) const;
  void StoreFixedPositions(const double* positions);
  void AddEnergyAndGradient(int t, double energy, const double* local_gradient, Assembly* assembly,
                            std::vector<double>* gradient) const;
  void AddConstantTerm(int t, Assembly* assembly, std::vector<double>* gradient) const;
  void StoreConstantTerm(int t, double energy, const double* local_gradient);

  const Model& model_;
  const DofMap& dofs_;
  const int generation_;  // model_.self_contact.generation when the pattern was built
  std::vector<int> column_starts_, rows_, diagonal_;
  // A local entry r * size + c of a term's Hessian and its index in the value arrays.
  struct ScatterEntry {
    int local;
    int destination;
  };
  // Term t's local Hessian is stored at term_offsets_[t] (size² entries); the entries it adds to
  // the value arrays are scatter_[scatter_starts_[t] .. scatter_starts_[t + 1]) (none for a fixed
  // coordinate's entries or those below the diagonal).
  std::vector<int> term_offsets_, scatter_starts_;
  std::vector<ScatterEntry> scatter_;
  std::vector<double> values_, projected_;
  EigenvalueFilter filter_ = EigenvalueFilter::kClamp;
  int threads_ = DefaultAssemblyThreads();
  bool active_set_ = true;
  // The constant terms (set_reuse_constant_terms): each term's slot (-1: it has a free coordinate),
  // the slots' stored energies and gradients, and the fixed coordinates with their values when
  // they were stored.
  bool reuse_constant_terms_ = true;
  bool constants_stored_ = false;
  std::vector<int> constant_slot_, constant_gradient_offsets_, fixed_coordinates_;
  std::vector<double> constant_energy_, constant_gradient_, stored_fixed_positions_;
  // One block of terms' local results (Assemble), reused between calls.
  enum TermStatus : char { kEvaluated, kProjected, kFailed, kSkipped, kConstant };
  std::vector<double> block_energy_, block_gradient_, block_hessian_, block_projected_;
  std::vector<int> block_gradient_offsets_;
  std::vector<TermStatus> block_status_;
};

class SparseCholesky {
 public:
  // Symbolic analysis of the pattern of `hessian` (which must outlive this object). Throws
  // std::bad_alloc when CHOLMOD runs out of memory (here, in Factorize or in Solve).
  explicit SparseCholesky(const FreeHessian& hessian);
  ~SparseCholesky();
  SparseCholesky(const SparseCholesky&) = delete;
  SparseCholesky& operator=(const SparseCholesky&) = delete;

  // Numeric factorisation of the matrix with upper triangle `values` plus diag(`shift`) (one per
  // free coordinate; may be null). False if it is not positive definite.
  bool Factorize(const std::vector<double>& values, const std::vector<double>* shift);
  // x = A⁻¹ b with the last successful factorisation.
  void Solve(const std::vector<double>& b, std::vector<double>* x);

  double last_factorization_seconds() const { return last_factorization_seconds_; }
  double factor_nonzeros() const;
  double factorization_flops() const { return common_.fl; }  // of the numeric factorisation

 private:
  void Release();
  [[noreturn]] void ReleaseAndThrowOutOfMemory();

  const FreeHessian& hessian_;
  cholmod_common common_;
  cholmod_sparse* matrix_ = nullptr;
  cholmod_factor* factor_ = nullptr;
  cholmod_dense* rhs_ = nullptr;
  double last_factorization_seconds_ = 0.0;
};

// One model's free coordinates, its FreeHessian and that pattern's CHOLMOD analysis, built once.
// RunSolve builds one and hands it to the solver (newton assembles and factorises in it) and then
// certifies the answer in it (round-off floor, stability): the certificate then needs no second
// pattern, analysis or factor of its own. The model must have a free coordinate and outlive it.
struct HessianWorkspace {
  explicit HessianWorkspace(const Model& model)
      : dofs(model), hessian(model, dofs), cholesky(hessian) {}
  const DofMap dofs;
  FreeHessian hessian;
  SparseCholesky cholesky;
};

}  // namespace drape

#endif  // DRAPE_SRC_NUMERICS_SPARSE_HESSIAN_H_
