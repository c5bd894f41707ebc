#pragma once
/// @file The stiffness the increment LCPs are solved on: K itself, or K condensed statically onto
/// a zone of blocks that holds every candidate point (condensed_stiffness.hpp). A zone costs a
/// factorization of K in a new order; a larger zone costs more in every active-set iteration. So
/// a zone is rings of neighbours around the blocks needed, with a margin, and K's order also
/// holds reserve zones around it (nested, each larger): a zone outgrown is replaced by the
/// smallest reserve that holds what is needed, read from the same factor. Where it pays, K is
/// condensed in two steps, onto a region and the region's S onto the zone: a zone outgrown
/// inside its region costs a factorization of the region's S instead of K's.
#include <memory>
#include <optional>
#include <vector>

#include <bimrock/assembly/yield_points.hpp>
#include <bimrock/model/model.hpp>
#include <bimrock/solve/condensed_stiffness.hpp>
#include <bimrock/solve/flexibility_columns.hpp>
#include <bimrock/solve/reduced_tangent.hpp>
#include <bimrock/solve/sparse_cholesky.hpp>
#include <bimrock/solve/stiffness_factor.hpp>

namespace bimrock {

/// How zones are chosen (expert tuning: the defaults are the method's).
struct ZoneTuning {
  /// The LCPs are solved on K condensed onto a zone while that zone is at most this fraction of
  /// the model; a larger one is not worth it, and K itself is used (0: never condense, 1:
  /// always). A zone has at least least_zone_blocks blocks.
  double condensed_zone_fraction = 0.5;
  int least_zone_blocks = 200;
  /// K is condensed only once the LCPs need more than this many blocks: before, K's few
  /// columns K^-1 phi cost less than factorizing K in a new order (0: condense at once).
  int condense_after_blocks = 16;
  /// Reserve zones in K's order around each zone (0: none).
  int zone_reserves = 2;
  /// A region has this many times the zone's blocks (0: no regions, zones condensed from K),
  /// and at most region_fraction of the model's.
  double region_growth = 4.0;
  double region_fraction = 0.25;
};

/// What condensing cost, for the analysis' statistics.
struct ZoneStatistics {
  int condensations = 0;     ///< times K (or a region's S) was factorized in a zone's order
  int reserve_switches = 0;  ///< times a zone was replaced by a reserve of the same factor
  int regions = 0;           ///< times K was condensed onto a region
  int zone_blocks = 0;       ///< blocks of the zone in use
  CholeskyWork tangent;      ///< factorizations and solves of the reduced tangents
  CholeskyWork condensed;    ///< solves with the condensed stiffnesses S
};

class StiffnessZones {
 public:
  /// `k` is K's factor (condensing onto a region, or reordered for a zone), `k_lower` K's
  /// lower triangle; both must outlive this. Where `k` is not reorderable, zones are condensed
  /// from regions only, and K itself is used where no region holds them.
  StiffnessZones(const Model& model, StiffnessFactor& k, const SparseMatrix& k_lower,
                 const ZoneTuning& tuning);

  /// Makes the stiffness hold every flagged block (per block of the model): the zone in use if
  /// it does, else a reserve of its factor, else a new zone. What was kept in S's unknowns goes
  /// with a zone.
  void hold(const std::vector<char>& needed);
  /// Whether both blocks of a yield point are in the zone (every point when K is not condensed).
  [[nodiscard]] bool covers(const YieldPoint& point) const;

  /// The stiffness in use (hold() must have been called once).
  [[nodiscard]] const CondensedStiffness& stiffness() const { return *condensed_; }
  /// Its flexibility columns S^-1 phi_r, kept across rounds while the zone is the same.
  [[nodiscard]] FlexibilityColumns& columns() { return *columns_; }
  /// Its reduced tangent's factor, kept likewise.
  [[nodiscard]] TangentFactor& tangent() { return *tangent_; }

  [[nodiscard]] ZoneStatistics statistics() const;

 private:
  [[nodiscard]] const CondensedStiffness& base() const { return region_ ? *region_ : whole_k_; }
  SparseCholesky& base_factor() { return region_ ? region_factor_ : *k_.reorderable(); }
  int plan(const std::vector<char>& needed, int target, double most);
  void make_region(const std::vector<char>& needed, int target, double most);
  void condense_region(const std::vector<char>& region);
  void drop_region();
  [[nodiscard]] bool holds(const std::vector<char>& needed, int level) const;
  void use(int level);
  void whole();
  void retire();
  void emplace_solvers();

  const Model& model_;
  StiffnessFactor& k_;
  const SparseMatrix& k_lower_;
  ZoneTuning tuning_;
  const CondensedStiffness whole_k_;  // K itself: the base of a region, or of zones without one
  // The region: K condensed onto it, without a factor of its own (null: none, the zones are
  // condensed from K itself), and its S factorized in the order of the zones inside it.
  std::unique_ptr<CondensedStiffness> region_;
  std::vector<char> region_inside_;  // per block of the model: the region's, its edge excluded
  SparseCholesky region_factor_;
  std::vector<char> levels_;  // per block of the model: the nested zones of the base's order
  int level_ = 0;             // the zone in use: blocks of levels >= level_ (0: the whole model)
  std::unique_ptr<CondensedStiffness> condensed_;
  std::optional<FlexibilityColumns> columns_;
  std::optional<TangentFactor> tangent_;
  CholeskyWork retired_tangent_;  // the work of tangents of earlier zones
  CholeskyWork retired_s_;        // and of their solves with S
  ZoneStatistics counts_;
  int last_zone_ = 0;    // blocks of the last zone planned (not of its reserves)
  int last_region_ = 0;  // blocks of the last region
};

}  // namespace bimrock
