#pragma once
/// @file The stiffness condensed statically onto the plastic zone. Yield rows touch
/// only the unknowns of the blocks their points join: with P the unknowns of a zone of blocks
/// that holds every candidate point of an increment and E the others, the LCP matrix (eq. 28)
///
///   M = N - C K^-1 Phi = N - C_P S^-1 Phi_P,   S = K_PP - K_PE K_EE^-1 K_EP,
///
/// and the reduced tangent K - Phi_A N_AA^-1 C_A becomes S - Phi_PA N_AA^-1 C_AP. S is the
/// trailing part of K's factor when K is ordered with the zone last (L_PP L_PP^T = S), so it
/// costs one factorization of K; each active-set iteration then factorizes a matrix of the
/// zone's size instead of the whole model's, and each column of K^-1 Phi is a solve with S
/// through that trailing block (SchurSolver: S is not factorized again). The displacements of
/// the whole model are solves with K's factor, once per round.
///
/// A condensation may start from another one: K condensed onto a region R, then R's S
/// condensed onto a zone inside it. Condensing in steps gives the same S (Schur complements
/// compose: eliminating E then R \ P is eliminating E u (R \ P)), and a zone that outgrows
/// itself inside R costs a factorization of R's S, not of K.
#include <limits>
#include <memory>
#include <vector>

#include <Eigen/Core>

#include <bimrock/assembly/yield_system.hpp>
#include <bimrock/solve/schur_solver.hpp>
#include <bimrock/solve/sparse_cholesky.hpp>

namespace bimrock {

class CondensedStiffness {
 public:
  /// No condensation: S is K and its factor K's.
  CondensedStiffness(const SpdSolver& k, const SparseMatrix& k_lower);
  /// `base` condensed onto its zone of blocks of level >= `level`: `factor` is base's S
  /// factorized in the order of levels given per block of base (SparseCholesky::analyze_last);
  /// this S is read from it, and solved through it if `solvable` (else factor() must not be
  /// used: the S of a region is factorized in the order of the zones inside it). `factor` must
  /// then outlive this and stay as it is.
  CondensedStiffness(const CondensedStiffness& base, const SparseCholesky& factor, int level,
                     bool solvable = true);

  /// K condensed onto the blocks `region` flags (per block of the model) as a region, its S
  /// given: the lower triangle, in the unknowns of the region's blocks in ascending order (6
  /// each). It has no factor: factor() must not be used.
  CondensedStiffness(const std::vector<char>& region, SparseMatrix s_lower);

  CondensedStiffness(const CondensedStiffness&) = delete;
  CondensedStiffness& operator=(const CondensedStiffness&) = delete;

  /// S = K: nothing condensed.
  [[nodiscard]] bool whole() const { return zone_.empty(); }
  [[nodiscard]] bool covers(int block) const {
    return whole() || zone_[static_cast<std::size_t>(block)] != 0;
  }
  /// Blocks of the zone (all of them when whole()).
  [[nodiscard]] int zone_blocks() const { return static_cast<int>(blocks_.size()); }
  /// The model's blocks in the order of S's unknowns (6 each).
  [[nodiscard]] const std::vector<int>& blocks() const { return blocks_; }
  /// Per block of S (in the order of blocks()), the value `per_model_block` gives its block.
  [[nodiscard]] std::vector<char> on_blocks(const std::vector<char>& per_model_block) const;
  /// S, lower triangle, in the unknowns' order of local().
  [[nodiscard]] const SparseMatrix& lower() const { return *lower_; }
  /// Solves with S: K's factor, or the trailing block of the factor S was read from.
  [[nodiscard]] const SpdSolver& factor() const;

  /// The yield rows with C and Phi in S's unknowns. Throws std::logic_error if a row touches an
  /// unknown outside the zone (its terms would be lost).
  [[nodiscard]] YieldSystem local(const YieldSystem& sys) const;
  /// A vector of K's unknowns restricted to S's (its entries outside the zone are dropped).
  [[nodiscard]] Eigen::VectorXd local(const Eigen::VectorXd& v) const;

 private:
  std::vector<char> zone_;  // per block of the model; empty when whole()
  std::vector<int> blocks_;
  SparseMatrix select_;     // n x |P|: column k picks the unknown of S's k-th (empty when whole())
  SparseMatrix own_lower_;  // S when condensed
  std::unique_ptr<SchurSolver> schur_solver_;
  const SparseMatrix* lower_ = nullptr;
  const SpdSolver* factor_ = nullptr;
};

/// The blocks of `needed` and rings of their neighbours (blocks that share an interface), ring
/// by ring, until at least `target` blocks are flagged, `rings` rings are added, or no block is
/// left to add. With `within`, only blocks it flags are added.
std::vector<char> grow_zone(const Model& model, std::vector<char> needed, int target,
                            const std::vector<char>* within = nullptr,
                            int rings = std::numeric_limits<int>::max());

/// The blocks of `region` none of whose neighbours is outside it.
std::vector<char> interior(const Model& model, const std::vector<char>& region);

/// Lowers each block's level to at most one above the lowest of its neighbours', so that the
/// zones of levels >= 1 nest as SparseCholesky::analyze_last needs (a zone's rings cut short,
/// e.g. by a region's edge, leave blocks next to others two levels lower).
void nest_levels(const Model& model, std::vector<char>& levels);

}  // namespace bimrock
