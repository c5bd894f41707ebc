#pragma once
/// @file K's factor as the increments stand on it (docs/solution-strategy.md): solves with K,
/// and K condensed statically onto a region of blocks, the base that zones are condensed from
/// (stiffness_zones.hpp). CholmodStiffnessFactor factorizes K in this process; its factor is
/// also factorized again with a region or a zone last, so that S is read from its trailing
/// block. The PETSc backend factorizes K across the processes of an MPI run instead
/// (petsc/distributed_factor.hpp): it condenses onto regions only, and zones are condensed from
/// a region's S in every process.
#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

#include <bimrock/assembly/global_system.hpp>
#include <bimrock/model/presence.hpp>
#include <bimrock/solve/condensed_stiffness.hpp>
#include <bimrock/solve/sparse_cholesky.hpp>

namespace bimrock {

class StiffnessFactor {
 public:
  virtual ~StiffnessFactor() = default;
  StiffnessFactor(const StiffnessFactor&) = delete;
  StiffnessFactor& operator=(const StiffnessFactor&) = delete;

  /// Solves with K.
  [[nodiscard]] virtual const SpdSolver& solver() const = 0;
  /// K (`whole`, which holds this factor's solver()) condensed onto the blocks `region` flags
  /// (per block of the model), as a region: without a factor of its own.
  [[nodiscard]] virtual std::unique_ptr<CondensedStiffness> condense(
      const CondensedStiffness& whole, const std::vector<char>& region) = 0;
  /// The factor of K that may be factorized again in the order of nested zones
  /// (SparseCholesky::analyze_last) to condense zones straight from K; null where zones are
  /// condensed from regions only.
  [[nodiscard]] virtual SparseCholesky* reorderable() = 0;

 protected:
  StiffnessFactor() = default;
};

/// K factorized by CHOLMOD in this process.
class CholmodStiffnessFactor final : public StiffnessFactor {
 public:
  /// `lower` (K's lower triangle) must outlive this.
  explicit CholmodStiffnessFactor(const SparseMatrix& lower);
  /// Analyzes and factorizes K; false if it is not positive definite (failed_column() then
  /// names the column where the factorization broke down).
  [[nodiscard]] bool factorize();
  [[nodiscard]] std::int64_t failed_column() const { return k_.failed_column(); }

  [[nodiscard]] const SpdSolver& solver() const override { return k_; }
  /// K's factor again with the region last, and S read from its trailing block.
  [[nodiscard]] std::unique_ptr<CondensedStiffness> condense(
      const CondensedStiffness& whole, const std::vector<char>& region) override;
  [[nodiscard]] SparseCholesky* reorderable() override { return &k_; }

 private:
  const SparseMatrix& lower_;
  SparseCholesky k_;
};

/// Makes the factor of K for the blocks `present`, from K's lower triangle `lower` (which
/// outlives the factor). Throws ModelError where K is singular.
using StiffnessFactorization = std::function<std::unique_ptr<StiffnessFactor>(
    const Presence& present, const SparseMatrix& lower)>;

}  // namespace bimrock
