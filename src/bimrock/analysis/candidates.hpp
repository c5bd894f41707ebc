#pragma once
/// @file The candidate points of an increment's LCP: the points whose rows it holds. Required
/// are the open points and those whose elastic predictor reaches yield; later rounds add the
/// points the check of every yield function found violated. Rows of points that stay below
/// yield cost only their share of the LCP, where a point left out and then violated costs a
/// further round (LCP, update, check of every point): so points near yield, and on the reduced
/// tangent the points around the last plastic flow, join while the zone the LCP is solved on
/// holds them anyway.
#include <cstddef>
#include <set>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include <bimrock/assembly/yield_points.hpp>
#include <bimrock/assembly/yield_values.hpp>
#include <bimrock/model/model.hpp>
#include <bimrock/solve/increment_solver.hpp>

namespace bimrock {

/// Expert tuning of the candidates; the defaults are the method's.
struct CandidateTuning {
  /// A point joins where its predictor f + df comes within margin |df| of yield (the nearest
  /// first, at most two per point that reaches it; 0: only points that reach yield).
  double margin = 3.0;
  /// Where the last increment ran on the reduced tangent, the points within this many rings of
  /// neighbours of the plastic flow's blocks join too (0: none).
  int near_rings = 2;
};

class Candidates {
 public:
  /// The first round's candidates: points open (gap > 0) or whose predicted yield functions
  /// `predicted` exceed `tol`, then the nearest ones within the margin of their change from
  /// `now`; with `flow` (the (point, mode) rows of the last plastic flow), the points around it.
  Candidates(const Model& model, const std::vector<YieldPoint>& points,
             const std::vector<PlasticState>& states, const YieldValues& now,
             const YieldValues& predicted, double tol, const CandidateTuning& tuning,
             const std::set<std::pair<int, int>>* flow);

  /// Per block of the model: the blocks the required points touch (none: the LCP is empty).
  [[nodiscard]] std::vector<char> required_blocks() const;
  /// The points of this round's LCP: the required ones, and the others the zone covers.
  [[nodiscard]] std::vector<int> in_lcp(const IncrementSolver& solver) const;
  /// Makes the violated points required. For each one that was outside the LCP, at most two
  /// points that this round's plastic flow moved towards yield (f - predicted, the change the
  /// predictor did not foresee) join where that change, margin times over, reaches yield.
  /// Returns how many violated points were outside.
  std::size_t require(const std::vector<int>& violated, const YieldValues& f,
                      const IncrementSolver& solver);
  /// Whether the points around the flow are candidates; drop_around() removes them (a round on
  /// them that stalls goes on without them).
  [[nodiscard]] bool around() const { return around_; }
  void drop_around();

 private:
  [[nodiscard]] bool in_lcp(std::size_t p, const IncrementSolver& solver) const;
  void join_nearest(const YieldValues& f, const Eigen::VectorXd& df, std::size_t most);
  void join_around(const std::set<std::pair<int, int>>& flow);

  const Model& model_;
  const std::vector<YieldPoint>& points_;
  const YieldValues& predicted_;
  double tol_;
  CandidateTuning tuning_;
  enum Candidacy : char { kNone = 0, kRequired = 1, kNear = 2, kAround = 3 };
  std::vector<char> candidacy_;  // per point
  bool around_ = false;
};

}  // namespace bimrock
