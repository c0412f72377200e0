#include "src/numerics/sparse_hessian.h"

#include <Eigen/Core>
#include <algorithm>
#include <cassert>
#include <chrono>
#include <cmath>
#include <new>
#include <thread>

#include "src/numerics/library_threads.h"

namespace drape {

namespace {

// A translation-invariant 2-node term's Hessian is [A −A; −A A] = [1 −1; −1 1] ⊗ A
// (src/model/term.h builds it so, exactly): its eigenvalues are 0 and 2·eig(A), and projecting A
// projects the whole.
bool ProjectSpringLike(EigenvalueFilter filter, double* row_major) {
  Eigen::Map<Eigen::Matrix<double, 6, 6, Eigen::RowMajor>> matrix(row_major);
  const Eigen::Matrix3d block = matrix.topLeftCorner<3, 3>();
  if (matrix.topRightCorner<3, 3>() != -block || matrix.bottomLeftCorner<3, 3>() != -block ||
      matrix.bottomRightCorner<3, 3>() != block) {
    return ProjectSymmetric<6>(filter, 6, row_major);
  }
  Eigen::Matrix<double, 3, 3, Eigen::RowMajor> projected = block;
  if (!ProjectSymmetric<3>(filter, 3, projected.data())) return false;
  matrix << projected, -projected, -projected, projected;
  return true;
}

bool ProjectToPositiveSemidefinite(EigenvalueFilter filter, int n, double* row_major) {
  switch (n) {
    case 3:
      return ProjectSymmetric<3>(filter, n, row_major);
    case 6:
      return ProjectSpringLike(filter, row_major);
    case 9:
      return ProjectSymmetric<9>(filter, n, row_major);
    case 12:
      return ProjectSymmetric<12>(filter, n, row_major);
    case 15:  // the finite-volume bending term (5 nodes)
      return ProjectSymmetric<15>(filter, n, row_major);
    default:
      return ProjectSymmetric<Eigen::Dynamic>(filter, n, row_major);
  }
}

}  // namespace

FreeHessian::FreeHessian(const Model& model, const DofMap& dofs)
    : model_(model), dofs_(dofs), generation_(model.self_contact.generation) {
  BuildPattern();
  BuildDestinations();
  FindConstantTerms();
  values_.assign(rows_.size(), 0.0);
  projected_.assign(rows_.size(), 0.0);
}

void FreeHessian::BuildPattern() {
  const std::vector<int>& to_free = dofs_.global_to_free();
  std::vector<std::vector<int>> column_rows(size());
  std::vector<int> free;
  for (const auto& term : model_.terms) {
    free.clear();
    for (int node : term->nodes()) {
      for (int c = 0; c < 3; ++c) {
        if (to_free[3 * node + c] >= 0) free.push_back(to_free[3 * node + c]);
      }
    }
    for (int row : free) {
      for (int column : free) {
        if (row <= column) column_rows[column].push_back(row);
      }
    }
  }
  column_starts_.assign(size() + 1, 0);
  diagonal_.assign(size(), -1);
  for (int column = 0; column < size(); ++column) {
    auto& rows = column_rows[column];
    rows.push_back(column);  // every diagonal entry exists, for the regularisation
    std::sort(rows.begin(), rows.end());
    rows.erase(std::unique(rows.begin(), rows.end()), rows.end());
    column_starts_[column + 1] = column_starts_[column] + static_cast<int>(rows.size());
  }
  rows_.reserve(column_starts_.back());
  for (int column = 0; column < size(); ++column) {
    rows_.insert(rows_.end(), column_rows[column].begin(), column_rows[column].end());
    std::vector<int>().swap(column_rows[column]);
    diagonal_[column] = column_starts_[column + 1] - 1;  // rows are sorted, the diagonal is last
  }
}

void FreeHessian::BuildDestinations() {
  const std::vector<int>& to_free = dofs_.global_to_free();
  term_offsets_.reserve(model_.terms.size() + 1);
  term_offsets_.push_back(0);
  scatter_starts_.reserve(model_.terms.size() + 1);
  scatter_starts_.push_back(0);
  for (const auto& term : model_.terms) {
    const int n = term->num_coordinates();
    const auto& nodes = term->nodes();
    for (int r = 0; r < n; ++r) {
      const int row = to_free[3 * nodes[r / 3] + r % 3];
      for (int c = 0; c < n; ++c) {
        const int column = to_free[3 * nodes[c / 3] + c % 3];
        if (row < 0 || column < 0 || row > column) continue;
        const auto first = rows_.begin() + column_starts_[column];
        const auto last = rows_.begin() + column_starts_[column + 1];
        const int destination =
            static_cast<int>(std::lower_bound(first, last, row) - rows_.begin());
        scatter_.push_back({r * n + c, destination});
      }
    }
    term_offsets_.push_back(term_offsets_.back() + n * n);
    scatter_starts_.push_back(static_cast<int>(scatter_.size()));
  }
}

// A term with a free coordinate scatters at least that coordinate's diagonal entry; a constant
// term scatters nothing.
void FreeHessian::FindConstantTerms() {
  constant_slot_.assign(model_.terms.size(), -1);
  constant_gradient_offsets_.assign(1, 0);
  for (size_t t = 0; t < model_.terms.size(); ++t) {
    if (scatter_starts_[t + 1] > scatter_starts_[t]) continue;
    constant_slot_[t] = static_cast<int>(constant_gradient_offsets_.size()) - 1;
    constant_gradient_offsets_.push_back(constant_gradient_offsets_.back() +
                                         model_.terms[t]->num_coordinates());
  }
  constant_energy_.assign(constant_gradient_offsets_.size() - 1, 0.0);
  constant_gradient_.assign(constant_gradient_offsets_.back(), 0.0);
  const std::vector<int>& to_free = dofs_.global_to_free();
  for (int k = 0; k < model_.num_dofs(); ++k) {
    if (to_free[k] < 0) fixed_coordinates_.push_back(k);
  }
}

bool FreeHessian::FixedPositionsAsStored(const double* positions) const {
  for (size_t f = 0; f < fixed_coordinates_.size(); ++f) {
    const double now = positions[fixed_coordinates_[f]];
    const double stored = stored_fixed_positions_[f];
    if (now != stored || std::signbit(now) != std::signbit(stored)) return false;  // NaN: changed
  }
  return true;
}

void FreeHessian::StoreFixedPositions(const double* positions) {
  stored_fixed_positions_.resize(fixed_coordinates_.size());
  for (size_t f = 0; f < fixed_coordinates_.size(); ++f) {
    stored_fixed_positions_[f] = positions[fixed_coordinates_[f]];
  }
}

// Adds term t's energy and local gradient into the assembly.
void FreeHessian::AddEnergyAndGradient(int t, double energy, const double* local_gradient,
                                       Assembly* assembly, std::vector<double>* gradient) const {
  assembly->energy += energy;
  assembly->energy_magnitude += std::abs(energy);
  const Term& term = *model_.terms[t];
  const auto& nodes = term.nodes();
  for (int k = 0; k < term.num_coordinates(); ++k) {
    (*gradient)[3 * nodes[k / 3] + k % 3] += local_gradient[k];
  }
}

void FreeHessian::AddConstantTerm(int t, Assembly* assembly, std::vector<double>* gradient) const {
  const int slot = constant_slot_[t];
  ++assembly->reused_terms;
  AddEnergyAndGradient(t, constant_energy_[slot],
                       constant_gradient_.data() + constant_gradient_offsets_[slot], assembly,
                       gradient);
}

void FreeHessian::StoreConstantTerm(int t, double energy, const double* local_gradient) {
  const int slot = constant_slot_[t];
  constant_energy_[slot] = energy;
  std::copy(local_gradient, local_gradient + model_.terms[t]->num_coordinates(),
            constant_gradient_.begin() + constant_gradient_offsets_[slot]);
}

namespace {

// Runs work(begin, end) over [0, count) split into `threads` contiguous parts, one per thread (the
// calling thread takes the first). Which thread computes a part does not change any result.
template <typename Work>
void ParallelFor(int count, int threads, const Work& work) {
  threads = std::max(1, std::min(threads, count));
  if (threads == 1) {
    work(0, count);
    return;
  }
  std::vector<std::thread> pool;
  pool.reserve(threads - 1);
  for (int k = 1; k < threads; ++k) {
    pool.emplace_back(work, static_cast<int>(static_cast<long>(count) * k / threads),
                      static_cast<int>(static_cast<long>(count) * (k + 1) / threads));
  }
  work(0, static_cast<int>(static_cast<long>(count) / threads));
  for (auto& thread : pool) thread.join();
}

constexpr int kTermsPerBlock = 8192;  // local results held at once: a few MB

// One term's energy, gradient and Hessian at `positions`, and when `projected` is given, its
// Hessian made semidefinite there (`*changed` whether that changed it). False if not evaluable.
bool EvaluateTerm(const Term& term, const double* positions, EigenvalueFilter filter,
                  double* energy, double* gradient, double* hessian, double* projected,
                  bool* changed) {
  *changed = false;
  if (projected != nullptr && term.HasStagedProjection()) {
    return term.EnergyHessianProjected(positions, filter, energy, gradient, hessian, projected,
                                       changed);
  }
  if (!term.EnergyHessian(positions, energy, gradient, hessian)) return false;
  if (projected == nullptr) return true;
  const int n = term.num_coordinates();
  std::copy(hessian, hessian + n * n, projected);
  *changed = ProjectToPositiveSemidefinite(filter, n, projected);
  return true;
}

// Adds a term's local matrix `local` into `values` along its scatter entries [begin, end), and,
// when given, its local stand-in `local_projected` into `projected` (one pass over the entries).
template <typename Entry>
void AddLocalMatrices(const Entry* begin, const Entry* end, const double* local, double* values,
                      const double* local_projected, double* projected) {
  if (local_projected == nullptr) {
    for (const Entry* e = begin; e != end; ++e) values[e->destination] += local[e->local];
    return;
  }
  for (const Entry* e = begin; e != end; ++e) {
    values[e->destination] += local[e->local];
    projected[e->destination] += local_projected[e->local];
  }
}

// Makes `buffer` hold at least `size` elements, never shrinking it: a shorter last block of terms
// followed by a full first one would otherwise zero-fill megabytes on every assembly.
template <typename T>
void GrowTo(int size, std::vector<T>* buffer) {
  if (static_cast<int>(buffer->size()) < size) buffer->resize(size);
}

}  // namespace

int DefaultAssemblyThreads() { return std::max(1u, std::thread::hardware_concurrency()); }

// Terms are taken in blocks: the local energies, gradients and (projected) Hessians of a block's
// terms are computed in parallel into per-term storage, then added into the global arrays by one
// thread in term order, so that every sum is made in the same order whatever the thread count.
bool FreeHessian::Assemble(const double* positions, bool project, Assembly* assembly,
                           std::vector<double>* gradient) {
  *assembly = Assembly();
  assert(!Stale() && "the model's terms changed since the pattern was built");
  gradient->assign(model_.num_dofs(), 0.0);
  std::fill(values_.begin(), values_.end(), 0.0);
  if (project) std::fill(projected_.begin(), projected_.end(), 0.0);
  // The constant terms' stored values hold while no fixed coordinate has moved; else this assembly
  // evaluates them and stores them anew.
  const bool reuse =
      reuse_constant_terms_ && constants_stored_ && FixedPositionsAsStored(positions);
  if (!reuse) constants_stored_ = false;
  const int num_terms = static_cast<int>(model_.terms.size());
  for (int first = 0; first < num_terms; first += kTermsPerBlock) {
    const int last = std::min(num_terms, first + kTermsPerBlock);
    const int count = last - first;
    GrowTo(count, &block_energy_);
    GrowTo(count, &block_status_);
    GrowTo(count + 1, &block_gradient_offsets_);
    block_gradient_offsets_[0] = 0;
    for (int t = first; t < last; ++t) {
      block_gradient_offsets_[t - first + 1] =
          block_gradient_offsets_[t - first] + model_.terms[t]->num_coordinates();
    }
    const int base = term_offsets_[first];
    GrowTo(block_gradient_offsets_[count], &block_gradient_);
    GrowTo(term_offsets_[last] - base, &block_hessian_);
    if (project) GrowTo(term_offsets_[last] - base, &block_projected_);
    ParallelFor(count, threads_, [&](int begin, int end) {
      for (int i = begin; i < end; ++i) EvaluateBlockTerm(positions, project, reuse, first, i);
    });
    for (int i = 0; i < count; ++i) {
      if (block_status_[i] == kFailed) return false;
      AddBlockTerm(first, i, project, assembly, gradient);
    }
  }
  if (reuse_constant_terms_ && !reuse) {
    StoreFixedPositions(positions);
    constants_stored_ = true;
  }
  return std::isfinite(assembly->energy);
}

// Term first + i's local results into the block buffers, and its status: skipped outside the active
// set, constant where its stored values hold (`reuse`), else evaluated.
void FreeHessian::EvaluateBlockTerm(const double* positions, bool project, bool reuse, int first,
                                    int i) {
  const int t = first + i;
  if (active_set_ && !model_.terms[t]->Touches(positions)) {
    block_status_[i] = kSkipped;
    return;
  }
  if (reuse && constant_slot_[t] >= 0) {
    block_status_[i] = kConstant;
    return;
  }
  const int offset = term_offsets_[t] - term_offsets_[first];
  bool changed = false;
  const bool evaluated = EvaluateTerm(
      *model_.terms[t], positions, filter_, &block_energy_[i],
      block_gradient_.data() + block_gradient_offsets_[i], block_hessian_.data() + offset,
      project ? block_projected_.data() + offset : nullptr, &changed);
  block_status_[i] = !evaluated ? kFailed : (changed ? kProjected : kEvaluated);
}

// Adds term first + i's local results, held in the block buffers, into the assembly.
void FreeHessian::AddBlockTerm(int first, int i, bool project, Assembly* assembly,
                               std::vector<double>* gradient) {
  if (block_status_[i] == kSkipped) {  // its energy, gradient and Hessian are zero
    ++assembly->skipped_terms;
    return;
  }
  const int t = first + i;
  if (block_status_[i] == kConstant) {  // no Hessian entry: its stored energy and gradient
    AddConstantTerm(t, assembly, gradient);
    return;
  }
  const double* local_gradient = block_gradient_.data() + block_gradient_offsets_[i];
  AddEnergyAndGradient(t, block_energy_[i], local_gradient, assembly, gradient);
  if (constant_slot_[t] >= 0) {  // its scatter is empty: nothing reaches the Hessian
    StoreConstantTerm(t, block_energy_[i], local_gradient);
    return;
  }
  const double* local = block_hessian_.data() + term_offsets_[t] - term_offsets_[first];
  // An unchanged term's stand-in is its Hessian, equal to it bit for bit: read it once.
  const double* stand_in = nullptr;
  if (project) {
    const bool changed = block_status_[i] == kProjected;
    assembly->projected_terms += changed;
    stand_in = changed ? block_projected_.data() + term_offsets_[t] - term_offsets_[first] : local;
  }
  AddLocalMatrices(scatter_.data() + scatter_starts_[t], scatter_.data() + scatter_starts_[t + 1],
                   local, values_.data(), stand_in, projected_.data());
}

void FreeHessian::Multiply(const std::vector<double>& values, const double* x, double* y) const {
  std::fill(y, y + size(), 0.0);
  for (int column = 0; column < size(); ++column) {
    for (int p = column_starts_[column]; p < column_starts_[column + 1]; ++p) {
      const int row = rows_[p];
      y[row] += values[p] * x[column];
      if (row != column) y[column] += values[p] * x[row];
    }
  }
}

SparseCholesky::SparseCholesky(const FreeHessian& hessian) : hessian_(hessian) {
  assert(hessian.size() > 0);
  RunLibrariesOnOneThread();
  cholmod_start(&common_);
  common_.print = 0;                        // failures are reported by the return value
  common_.supernodal = CHOLMOD_SUPERNODAL;  // always the supernodal (BLAS-3) factorisation
  common_.quick_return_if_not_posdef = 1;   // an indefinite matrix fails fast
  const int n = hessian.size();
  matrix_ = cholmod_allocate_sparse(n, n, hessian.num_nonzeros(), /*sorted=*/1, /*packed=*/1,
                                    /*stype=*/1, CHOLMOD_REAL, &common_);
  if (!matrix_) ReleaseAndThrowOutOfMemory();
  std::copy(hessian.column_starts().begin(), hessian.column_starts().end(),
            static_cast<int*>(matrix_->p));
  std::copy(hessian.rows().begin(), hessian.rows().end(), static_cast<int*>(matrix_->i));
  std::fill_n(static_cast<double*>(matrix_->x), hessian.num_nonzeros(), 0.0);
  // Both orderings, the cheaper kept (src/numerics/sparse_hessian.h).
  common_.nmethods = 2;
  common_.method[0].ordering = CHOLMOD_AMD;
  common_.method[1].ordering = CHOLMOD_METIS;
  factor_ = cholmod_analyze(matrix_, &common_);
  rhs_ = cholmod_zeros(n, 1, CHOLMOD_REAL, &common_);
  if (!factor_ || !rhs_) ReleaseAndThrowOutOfMemory();
}

// CHOLMOD returns NULL when it runs out of memory (or fails otherwise): the constructor frees
// what it got and reports std::bad_alloc, which the command turns into "out of memory", exit 2.
void SparseCholesky::ReleaseAndThrowOutOfMemory() {
  Release();
  throw std::bad_alloc();
}

void SparseCholesky::Release() {
  if (rhs_) cholmod_free_dense(&rhs_, &common_);
  if (factor_) cholmod_free_factor(&factor_, &common_);
  if (matrix_) cholmod_free_sparse(&matrix_, &common_);
  cholmod_finish(&common_);
}

SparseCholesky::~SparseCholesky() { Release(); }

double SparseCholesky::factor_nonzeros() const { return common_.lnz; }

bool SparseCholesky::Factorize(const std::vector<double>& values,
                               const std::vector<double>* shift) {
  const auto start = std::chrono::steady_clock::now();
  double* x = static_cast<double*>(matrix_->x);
  std::copy(values.begin(), values.end(), x);
  if (shift) {
    for (int k = 0; k < hessian_.size(); ++k) x[hessian_.diagonal()[k]] += (*shift)[k];
  }
  const int ok = cholmod_factorize(matrix_, factor_, &common_);
  last_factorization_seconds_ =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (common_.status == CHOLMOD_OUT_OF_MEMORY) throw std::bad_alloc();
  return ok && common_.status == CHOLMOD_OK && factor_->minor == factor_->n;
}

void SparseCholesky::Solve(const std::vector<double>& b, std::vector<double>* x) {
  std::copy(b.begin(), b.end(), static_cast<double*>(rhs_->x));
  cholmod_dense* solution = cholmod_solve(CHOLMOD_A, factor_, rhs_, &common_);
  if (!solution) throw std::bad_alloc();
  const double* values = static_cast<const double*>(solution->x);
  x->assign(values, values + hessian_.size());
  cholmod_free_dense(&solution, &common_);
}

}  // namespace drape
