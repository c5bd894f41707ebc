#include <bimrock/analysis/plastic_analysis.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <memory>
#include <optional>
#include <set>
#include <stdexcept>
#include <utility>

#include <bimrock/analysis/condensed_stiffness.hpp>
#include <bimrock/analysis/field_results.hpp>
#include <bimrock/analysis/flexibility_columns.hpp>
#include <bimrock/analysis/support_check.hpp>
#include <bimrock/assembly/kinematics.hpp>
#include <bimrock/assembly/yield_values.hpp>
#include <bimrock/solve/active_set_lcp.hpp>
#include <bimrock/solve/branch_and_bound_lcp.hpp>
#include <bimrock/solve/factor_memory.hpp>
#include <bimrock/solve/lemke.hpp>
#include <bimrock/solve/reduced_tangent.hpp>
#include <bimrock/solve/sparse_cholesky.hpp>
#include <bimrock/solve/unsymmetric_tangent.hpp>
#include <bimrock/solve/working_set_lcp.hpp>

namespace bimrock {
namespace {

/// Plastic displacements of a load-controlled step more than this many times its elastic ones
/// are a mechanism resolved only by round-off (see try_increment).
constexpr double kMechanismRatio = 1e6;
/// What a point is to an increment's LCP: a required candidate (open, or its predictor reaches
/// yield, or a round violated it), a near one (within the candidate margin: its rows only save a
/// round, so it joins only where the condensed zone holds it already), one near the plastic flow
/// (PlasticOptions::near_rings: likewise), or neither.
enum Candidacy : char { kNone = 0, kRequired = 1, kNear = 2, kAround = 3 };
/// Candidates within the margin of yield (PlasticOptions::candidate_margin), at most this many
/// per point that reaches it (or, in a later round, per violated point added).
constexpr std::size_t kNearPerReached = 2;
/// Where a collapse certificate bounds the collapse load, the bisection's trials go this far
/// towards the bound (each carried one shrinks the bracket tenfold) until one fails.
constexpr double kAimAtBound = 0.9;

/// The zone K is condensed onto: rings of neighbours around the blocks of the required
/// candidate points, to kZoneGrowth times their number and kZoneRegrowth times the last zone
/// condensed onto first (at least PlasticOptions::least_zone_blocks). Each new zone costs a
/// factorization of K in a new order (~0.45 s at 10^4 blocks), a larger zone costs more in
/// every active-set iteration: measured on the plastic model of `bimrock bench`
/// (docs/performance.md). K's order also holds PlasticOptions::zone_reserves
/// reserve zones, each kReserveGrowth times the one inside it: a zone outgrown is replaced by
/// the smallest reserve that holds what is needed, read from the same factor (measured:
/// 5% less time at 10^5 blocks, 2% at 10^4; more reserves or finer ones made K's factor
/// larger for no gain).
constexpr double kZoneGrowth = 1.5;
constexpr double kZoneRegrowth = 1.2;
constexpr double kReserveGrowth = 1.25;
/// Regions (PlasticOptions::region_growth): a new one has at least kRegionRegrowth times the
/// blocks of the last one (a region outgrown is outgrown again as the plastic zone spreads),
/// and none is made that is not kRegionGrowthLeast times the zone's target
/// (PlasticOptions::region_fraction caps it).
constexpr double kRegionRegrowth = 2.0;
constexpr double kRegionGrowthLeast = 2.0;

// The LCP solvers and what they keep from one increment to the next.
struct LcpSolvers {
  LcpSolvers(SparseCholesky& k_factor, const SparseMatrix& k_matrix, const PlasticOptions& opt)
      : k(k_factor),
        k_lower(k_matrix),
        whole_k(k_factor, k_matrix),
        active_set(ActiveSetOptions{.max_iterations = opt.active_set_iterations,
                                    .interrupt_after = opt.interrupt_after}) {}
  SparseCholesky& k;  // K's factor: reordered when the region (or the zone) changes
  const SparseMatrix& k_lower;
  const CondensedStiffness whole_k;  // K itself: the base of a region, or of zones without one
  // The region (PlasticOptions::region_growth): K condensed onto it, without a factor of its own
  // (null: none, the zones are condensed from K itself), and its S factorized in the order of
  // the zones inside it.
  std::unique_ptr<CondensedStiffness> region;
  std::vector<char> region_inside;  // per block of the model: the region's, its edge excluded
  SparseCholesky region_factor;
  std::vector<char> levels;  // per block of the model: the nested zones of the base's order
  int level = 0;             // the zone condensed onto: blocks of levels >= level
  std::unique_ptr<CondensedStiffness> condensed;  // S: the LCP's stiffness (or K itself)
  ActiveSetLcp active_set;
  Lemke lemke;
  BranchAndBoundLcp complete;  // decides any LCP: the last resort (branch_and_bound_lcp.hpp)
  std::optional<FlexibilityColumns> columns;  // S^-1 phi_r of the rows that were ever active
  std::optional<TangentFactor> tangent;       // the reduced tangent (analysis and last factor)
  std::set<std::pair<int, int>> last_active;  // (point, mode) yielding in the last increment
  bool last_on_tangent = false;  // the last carried increment's LCP ran on the reduced tangent
  CholeskyWork retired_tangent;  // the work of tangents of earlier condensations
  CholeskyWork retired_s;        // and of their solves with S
  int condensations = 0;
  int reserve_switches = 0;
  int regions = 0;
  int interrupted_rounds = 0;
  int rounds_without_around = 0;
  int last_zone = 0;    // blocks of the last zone condensed onto first (not of its reserves)
  int last_region = 0;  // blocks of the last region

  // What zones are condensed from: the region's S, or K.
  [[nodiscard]] const CondensedStiffness& base() const { return region ? *region : whole_k; }
  SparseCholesky& base_factor() { return region ? region_factor : k; }
  [[nodiscard]] const SparseCholesky& base_factor() const { return region ? region_factor : k; }

  // Condenses K onto a zone that holds the blocks flagged in `needed`, unless the one it has
  // does: onto a reserve zone of the base's factor if one holds them, else onto a new zone (the
  // base factorized in a new order): inside the region if it holds the new zone, else inside a
  // new region (K factorized with the region last), or from K itself where a region would be
  // too large to be worth it. What was kept in S's unknowns goes.
  void condense(const Model& model, const std::vector<char>& needed, const PlasticOptions& opt) {
    // Few blocks needed and none condensed yet: K itself, until more are needed.
    if (condensations == 0 && size(needed) <= opt.condense_after_blocks) {
      if (!condensed)
        whole();
      return;
    }
    if (condensations > 0 && holds(needed, level))  // level 0: K itself holds every block
      return;
    for (int l = level - 1; l >= 1 && !levels.empty(); --l)
      if (holds(needed, l)) {
        retire();
        use(l);
        ++reserve_switches;
        report("reserve", needed);
        return;
      }
    // A margin around what is needed now, and more blocks than the last zone: a zone outgrown
    // once is outgrown again as the plastic zone spreads.
    const int target =
        std::max({opt.least_zone_blocks, static_cast<int>(kZoneGrowth * size(needed)),
                  static_cast<int>(kZoneRegrowth * last_zone)});
    retire();
    const double most = opt.condensed_zone_fraction * model.n_blocks();
    // Inside the region, if it still holds the new zone: where the region's edge cuts the
    // zone's rings, nest_levels() lowers them, and a zone that then misses a needed block asks
    // for a new region.
    int top = 0;
    if (region) {
      top = plan(model, needed, target, most, opt);
      if (!holds(needed, top))
        drop_region();
    }
    if (!region) {
      if (opt.region_growth > 0.0)
        make_region(model, needed, target, opt.region_growth,
                    std::min(most, opt.region_fraction * model.n_blocks()));
      top = plan(model, needed, target, most, opt);
      if (region && !holds(needed, top)) {  // only where the region was too small for it
        drop_region();
        top = plan(model, needed, target, most, opt);
      }
    }
    if (top == 0) {
      whole();
    } else {
      const SparseMatrix& s = base().lower();
      base_factor().analyze_last(s, 6, base().on_blocks(levels));
      if (!base_factor().factorize(s))
        throw std::logic_error("condense: K, positive definite before, is not now");
      use(top);
    }
    ++condensations;
    report("condensation", needed);
  }
  static int size(const std::vector<char>& z) {
    return static_cast<int>(std::count(z.begin(), z.end(), 1));
  }
  // The levels of a new zone of `target` blocks around `needed` and of its reserves (inside the
  // region if there is one), nested; the zone's level, or 0 where the zone would be more than
  // `most` blocks of K itself (not worth condensing).
  int plan(const Model& model, const std::vector<char>& needed, int target, double most,
           const PlasticOptions& opt) {
    const std::vector<char>* within = region ? &region_inside : nullptr;
    std::vector<char> zone = grow_zone(model, needed, target, within);
    last_zone = size(zone);
    if (!region && size(zone) > most)
      return 0;
    // The zone, then its reserves around it (while they are within the fraction): levels
    // counted from the outermost reserve, 1.
    std::vector<std::vector<char>> zones{std::move(zone)};
    for (int r = 0; r < opt.zone_reserves; ++r) {
      std::vector<char> outer = grow_zone(
          model, zones.back(), static_cast<int>(kReserveGrowth * size(zones.back())), within);
      if (size(outer) > most || size(outer) == size(zones.back()))
        break;
      zones.push_back(std::move(outer));
    }
    levels.assign(needed.size(), 0);
    for (const std::vector<char>& z : zones)
      for (std::size_t b = 0; b < z.size(); ++b)
        levels[b] = static_cast<char>(levels[b] + z[b]);
    if (within)  // a needed block off the region's inside stays out, and fails holds()
      for (std::size_t b = 0; b < levels.size(); ++b)
        levels[b] = (*within)[b] ? levels[b] : 0;
    nest_levels(model, levels);
    return static_cast<int>(zones.size());
  }
  // K condensed onto a region around `needed` of `growth` times the zone's target, at least
  // kRegionRegrowth times the last region, at most `most` blocks (K factorized with the region
  // last); none where that leaves no room for the zone to grow.
  void make_region(const Model& model, const std::vector<char>& needed, int target, double growth,
                   double most) {
    const double wanted = std::max(growth * target, kRegionRegrowth * last_region);
    const int blocks = static_cast<int>(std::min(wanted, most));
    if (blocks < kRegionGrowthLeast * target)
      return;
    std::vector<char> r = grow_zone(model, needed, blocks);
    if (size(r) > most)
      return;
    k.analyze_last(k_lower, 6, r);
    if (!k.factorize(k_lower))
      throw std::logic_error("condense: K, positive definite before, is not now");
    region = std::make_unique<CondensedStiffness>(whole_k, k, 1, false);
    // Zones keep off the region's edge, whose blocks its S couples all together.
    region_inside = interior(model, r);
    last_region = region->zone_blocks();
    ++regions;
  }
  void drop_region() {
    region.reset();
    region_inside.clear();
  }
  // Whether the zone `l` (0: the whole model) holds every flagged block.
  [[nodiscard]] bool holds(const std::vector<char>& needed, int l) const {
    if (l == 0)
      return true;
    for (std::size_t b = 0; b < needed.size(); ++b)
      if (needed[b] && levels[b] < l)
        return false;
    return true;
  }
  // Condenses onto zone l of the base's factor as it is.
  void use(int l) {
    level = l;
    condensed = std::make_unique<CondensedStiffness>(base(), base_factor(), l);
    emplace_solvers();
  }
  // No condensation: K itself, in its own order (the last zone's is as good for its solves).
  void whole() {
    level = 0;
    levels.clear();
    condensed = std::make_unique<CondensedStiffness>(k, k_lower);
    emplace_solvers();
  }
  // The work of the solvers that go, for the totals.
  void retire() {
    if (tangent)
      add(retired_tangent, tangent->cholesky.work());
    if (condensed && !condensed->whole())
      add(retired_s, condensed->factor().work());
    columns.reset();
    tangent.reset();
    condensed.reset();
  }
  void emplace_solvers() {
    // The columns kept may take 12 bytes per entry of S's factor, 1.5 times its values: they
    // set the peak of the dense route's increments (a third of it cost 2.5x the columns' time
    // at 10^4 blocks for 10% less peak).
    const SpdSolver& s = condensed->factor();
    columns.emplace(s, std::max<std::int64_t>(64 << 20, 12 * s.factor_nonzeros()));
    tangent.emplace();
  }
  void report(const char* what, const std::vector<char>& needed) const {
    if (std::getenv("BIMROCK_DEBUG_LCP"))
      std::fprintf(stderr,
                   "%s %d (+%d reserves, %d regions): %d blocks needed, zone of %d (level %d of "
                   "%d), region of %d, %lld entries in K's factor\n",
                   what, condensations, reserve_switches, regions,
                   static_cast<int>(std::count(needed.begin(), needed.end(), 1)),
                   condensed->zone_blocks(), level, base_factor().levels(),
                   region ? region->zone_blocks() : 0, static_cast<long long>(k.factor_nonzeros()));
  }
  static void add(CholeskyWork& total, const CholeskyWork& w) {
    total.factorizations += w.factorizations;
    total.solved_columns += w.solved_columns;
    total.factorize_seconds += w.factorize_seconds;
    total.solve_seconds += w.solve_seconds;
  }
};

// The LCP of one round given column by column (eqs. 24, 28): M = N - C K^-1 Phi, plus under
// displacement control the term that keeps the monitor on its path; q = -f0 - C dU_load,
// shifted by the old gaps because the unknown of an opening row is the total gap.
class IncrementLcp final : public LcpColumns {
 public:
  IncrementLcp(const YieldSystem& sys, const std::vector<YieldPoint>& points, FlexibilityColumns& y,
               Eigen::VectorXd q, const Eigen::VectorXd& gap_old, const Eigen::VectorXd* control,
               Eigen::VectorXd control_term)
      : sys_(sys),
        points_(points),
        y_(y),
        control_(control),
        control_term_(std::move(control_term)) {
    q_ = std::move(q);
    if (gap_old.size() > 0 && gap_old.cwiseAbs().maxCoeff() > 0.0)
      q_ -= times(gap_old);
  }
  // M v with one back-solve (no column of M formed).
  [[nodiscard]] Eigen::VectorXd times(const Eigen::VectorXd& v) {
    const Eigen::VectorXd y = y_.combine(sys_, v);
    Eigen::VectorXd out = sys_.n * v - sys_.c * y;
    if (control_)
      out += control_term_ * control_->dot(y);
    return out;
  }
  [[nodiscard]] Eigen::Index size() const override { return sys_.size(); }
  // The modes of one yield point: at most 2 independent at a joint point (sigma_n, tau), 3 at
  // a block (its plane stress components).
  [[nodiscard]] Eigen::Index group(Eigen::Index row) const override {
    return sys_.rows[static_cast<std::size_t>(row)].point;
  }
  [[nodiscard]] int group_rank(Eigen::Index row) const override {
    return points_[static_cast<std::size_t>(sys_.rows[static_cast<std::size_t>(row)].point)]
                   .is_interface()
               ? 2
               : 3;
  }
  // Associated flow (C = Phi^T, N symmetric) under load control: M is symmetric (the control
  // term is not).
  // Checked on first use only: solvers ask when a collapse is to be proven.
  [[nodiscard]] bool symmetric() const override {
    if (!symmetric_) {
      const SparseMatrix asymmetry = sys_.c - SparseMatrix(sys_.phi.transpose());
      const SparseMatrix n_asymmetry = sys_.n - SparseMatrix(sys_.n.transpose());
      symmetric_ = !control_ && asymmetry.norm() <= 1e-12 * sys_.c.norm() &&
                   n_asymmetry.norm() <= 1e-12 * sys_.n.norm();
    }
    return *symmetric_;
  }
  [[nodiscard]] const Eigen::VectorXd& q() const override { return q_; }
  [[nodiscard]] Eigen::MatrixXd columns(const std::vector<Eigen::Index>& cols) override {
    y_.prepare(sys_, cols);
    Eigen::MatrixXd out(size(), static_cast<Eigen::Index>(cols.size()));
    for (std::size_t k = 0; k < cols.size(); ++k) {
      const Eigen::VectorXd& y = y_.column(sys_, cols[k]);
      auto col = out.col(static_cast<Eigen::Index>(k));
      col = Eigen::VectorXd(sys_.n.col(cols[k])) - sys_.c * y;
      if (control_)
        col += control_term_ * control_->dot(y);
    }
    return out;
  }
  // The whole matrix, for Lemke (which needs every column).
  [[nodiscard]] LcpProblem dense() {
    std::vector<Eigen::Index> all(static_cast<std::size_t>(size()));
    for (Eigen::Index r = 0; r < size(); ++r)
      all[static_cast<std::size_t>(r)] = r;
    return {columns(all), q_};
  }

 private:
  const YieldSystem& sys_;
  const std::vector<YieldPoint>& points_;
  FlexibilityColumns& y_;
  const Eigen::VectorXd* control_;
  Eigen::VectorXd control_term_;
  Eigen::VectorXd q_;
  mutable std::optional<bool> symmetric_;
};

// What one stage needs besides the state: the factor of K and the stage's reference load.
struct StageContext {
  const Model& model;
  const std::vector<YieldPoint>& points;
  const SparseCholesky& k;
  const Stage& stage;
  const YieldEvaluator& yield;  // every yield function of every point, for the checks
  Eigen::VectorXd x_ref;        // K^-1 P_stage: displacement of the whole stage load, elastic
  Eigen::VectorXd control;      // displacement control: u_monitor . direction = control . U
  double control_rate = 0.0;    // control . x_ref
  Timings* timings = nullptr;   // phases of the increments: candidates, yield rows, LCP, check
};

struct Trial {
  enum class Status { carried, collapse, failed };
  Status status = Status::failed;
  AnalysisState next;
  std::vector<YieldRow> rows;
  Eigen::VectorXd lambda;  // increments of the multipliers (opening: of the gap)
  Eigen::VectorXd du;
  Eigen::VectorXd ray;           // collapse: Lemke's secondary ray, the mechanism's multipliers
  double proven_fraction = 1.0;  // collapse: the least fraction of the step its ray proves
  double kink = 1.0;             // < 1: the fraction of the step at which a softening law reached
                                 // its residual value (the step must stop there)
  int lcp_size = 0;
  int pivots = 0;
  int active_set_iterations = 0;
  int tangent_factorizations = 0;
  int rounds = 0;
};

// Marks as near candidates the points not yet candidates whose yield functions f reach tol within
// `margin` times their change `df` (flat as f; modes where it is positive), nearest first, at
// most `most`.
void join_nearest(const YieldValues& f, const Eigen::VectorXd& df, double tol, double margin,
                  std::size_t most, std::vector<char>& candidate) {
  std::vector<std::pair<double, std::size_t>> near;  // (margin it needs, point)
  for (std::size_t p = 0; p < candidate.size(); ++p) {
    if (candidate[p])
      continue;
    double needed = std::numeric_limits<double>::infinity();
    for (Eigen::Index i = f.first[p]; i < f.first[p + 1]; ++i)
      if (df(i) > 0.0)
        needed = std::min(needed, (tol - f.f(i)) / df(i));
    if (needed < margin)
      near.emplace_back(needed, p);
  }
  const std::size_t keep = std::min(near.size(), most);
  std::nth_element(near.begin(), near.begin() + static_cast<std::ptrdiff_t>(keep), near.end());
  for (std::size_t k = 0; k < keep; ++k)
    candidate[near[k].second] = kNear;
}

// The largest violation of any yield function (unscaled, in Pa) and the points that violate
// them by more than tol; `all` gets every value.
double check_all_yield_functions(const StageContext& ctx, const AnalysisState& s, double tol,
                                 std::vector<int>& violators, YieldValues& all) {
  ctx.yield.evaluate(s.points, s.u, all);
  double worst = -std::numeric_limits<double>::infinity();
  for (std::size_t p = 0; p < ctx.points.size(); ++p) {
    const double f = all.largest(p);
    worst = std::max(worst, f);
    if (f > tol)
      violators.push_back(static_cast<int>(p));
  }
  return worst;
}

// The fraction of the step at which the first softening law of a joint reaches its residual
// value (its slope changes there, so a linear step must not run past it), or 1.
double first_kink(const Model& model, const std::vector<YieldPoint>& points,
                  const AnalysisState& before, const AnalysisState& after) {
  double fraction = 1.0;
  auto crossing = [&](double old_kappa, double new_kappa, const Softening& law) {
    const double d = law.distance;
    if (!std::isfinite(d) || law.peak == law.residual)
      return;
    const double margin = Softening::kKinkTolerance * std::max(d, 1e-300);
    if (old_kappa < d - margin && new_kappa > d + margin)
      fraction = std::min(fraction, (d - old_kappa) / (new_kappa - old_kappa));
  };
  for (std::size_t p = 0; p < points.size(); ++p) {
    if (!points[p].is_interface())
      continue;
    const JointStrength& law = *model.joint_materials[points[p].material].strength;
    crossing(before.points[p].slip, after.points[p].slip, law.cohesion);
    crossing(before.points[p].slip, after.points[p].slip, law.friction);
    crossing(before.points[p].max_gap, after.points[p].max_gap, law.tensile);
  }
  return fraction;
}

void update_state(const YieldSystem& sys, const Eigen::VectorXd& lambda, const Eigen::VectorXd& z,
                  const std::vector<YieldPoint>& points, AnalysisState& s) {
  for (int r = 0; r < sys.size(); ++r) {
    const YieldRow& row = sys.rows[r];
    PlasticState& ps = s.points[row.point];
    if (points[row.point].is_interface() && row.mode == kOpeningMode) {
      ps.plastic(0) += lambda(r);
      ps.gap = z(r);
      ps.max_gap = std::max(ps.max_gap, ps.gap);
    } else {
      ps.plastic += sys.flow[r] * lambda(r);
      ps.slip += lambda(r);
    }
  }
}

// The (point, mode) rows a solve starts from after an LCP's multipliers z: the active ones and
// the joints whose gap changed (z is the total gap of an opening row).
std::set<std::pair<int, int>> active_rows(const YieldSystem& sys, const Eigen::VectorXd& z,
                                          const Eigen::VectorXd& gap_old) {
  std::set<std::pair<int, int>> rows;
  for (int r = 0; r < sys.size(); ++r)
    if (z(r) != gap_old(r) || z(r) > 0.0)
      rows.insert({sys.rows[r].point, sys.rows[r].mode});
  return rows;
}

// Adds to `rows` the modes of `points` whose yield function exceeds tol: a solve from the rows
// of a solution would find just these violated (w = -f), so they join it at once.
void add_violated_modes(const std::vector<int>& points, const YieldValues& f, double tol,
                        std::set<std::pair<int, int>>& rows) {
  for (int p : points) {
    const auto values = f.of(static_cast<std::size_t>(p));
    for (Eigen::Index k = 0; k < values.size(); ++k)
      if (values(k) > tol)
        rows.insert({p, static_cast<int>(k)});
  }
}

// Records a trial's last LCP and the rows active at its end (a failed trial: those it started
// its last round from), however the trial ends.
struct HintRecorder {
  TrialHints* hints;  // null: nothing to record
  const std::vector<int>& points;
  const std::set<std::pair<int, int>>& active;
  ~HintRecorder() {
    if (hints)
      hints->trials.push_back({points, {active.begin(), active.end()}});
  }
};

// The points whose blocks lie within `rings` rings of the plastic flow's (the blocks of the last
// increment's active rows and of this step's required points) join the candidates as near
// ones. On the reduced tangent a candidate row costs only its share of w = q + N z - C x, and
// the flow spreads to the neighbours of its blocks: one round holds what rounds added one after
// another (PlasticOptions::near_rings).
void join_around_flow(const StageContext& ctx, const std::set<std::pair<int, int>>& last_active,
                      int rings, std::vector<char>& candidate) {
  std::vector<char> blocks(static_cast<std::size_t>(ctx.model.n_blocks()), 0);
  for (const auto& [p, mode] : last_active)
    flag_blocks(ctx.points[static_cast<std::size_t>(p)], blocks);
  for (std::size_t p = 0; p < candidate.size(); ++p)
    if (candidate[p] == kRequired)
      flag_blocks(ctx.points[p], blocks);
  blocks = grow_zone(ctx.model, std::move(blocks), std::numeric_limits<int>::max(), nullptr, rings);
  for (std::size_t p = 0; p < candidate.size(); ++p) {
    const YieldPoint& point = ctx.points[p];
    if (candidate[p] == kNone && blocks[static_cast<std::size_t>(point.block_i)] &&
        (point.block_j == kGround || blocks[static_cast<std::size_t>(point.block_j)]))
      candidate[p] = kAround;
  }
}

// One increment from state s: `step` is the increment of the stage factor (load control) or of
// the prescribed displacement (displacement control).
Trial try_increment(const StageContext& ctx, const AnalysisState& s, double step,
                    const PlasticOptions& opt, LcpSolvers& solvers) {
  const Model& model = ctx.model;
  const bool control = ctx.stage.control.has_value();
  Trial t;
  LapTimer clock(ctx.timings);
  // predict_elastic: the increment if nothing yielded.
  const Eigen::VectorXd du_elastic = control
                                         ? Eigen::VectorXd((step / ctx.control_rate) * ctx.x_ref)
                                         : Eigen::VectorXd(step * ctx.x_ref);
  // select_candidate_rows: open points, and points whose elastic predictor reaches yield (by
  // more than the tolerance of the final check: a joint that sits exactly on its tension
  // cut-off, as the vertical joints of a free-standing wall do, is not a candidate for the
  // round-off of its stress); then the points nearest to it, within the candidate margin.
  // f is linear in the stress for a given plastic state, so f + df is f at U + dU.
  YieldValues now;
  YieldValues predicted_f;  // f + df, per mode
  double scale = 0.0;
  ctx.yield.evaluate(s.points, s.u, now, &scale);
  ctx.yield.evaluate(s.points, Eigen::VectorXd(s.u + du_elastic), predicted_f, &scale);
  const Eigen::VectorXd change_f = (predicted_f.f - now.f).cwiseAbs();  // |df|
  const double tol = opt.yield_tolerance * std::max(scale, 1.0);
  std::vector<char> candidate(ctx.points.size(), 0);
  std::size_t reached = 0;
  for (std::size_t p = 0; p < ctx.points.size(); ++p) {
    if (s.points[p].gap > 0.0 || predicted_f.largest(p) > tol) {
      candidate[p] = kRequired;
      ++reached;
    }
  }
  // No more than kNearPerReached for each point that reaches yield: a large step from an
  // unloaded state (a stage's first) brings nearly every point within the margin.
  join_nearest(predicted_f, change_f, tol, opt.candidate_margin, kNearPerReached * reached,
               candidate);
  // Whether the LCPs hold points around the flow (they go, if a round on them stalls).
  bool around = solvers.last_on_tangent && opt.near_rings > 0;
  if (around)
    join_around_flow(ctx, solvers.last_active, opt.near_rings, candidate);
  // The warm start: the rows that yielded in the last increment, then those of the last round
  // (a round adds only the points the last one violated: its solution is nearly this one's).
  std::set<std::pair<int, int>> warm_rows = solvers.last_active;
  TrialHints* hints = opt.hints;
  if (hints && hints->mode == TrialHints::Mode::replay && hints->next < hints->trials.size()) {
    // The oracle: the recorded trial's last LCP and its final active rows.
    const TrialHint& hint = hints->trials[hints->next++];
    std::fill(candidate.begin(), candidate.end(), kNone);
    for (int p : hint.points)
      candidate[static_cast<std::size_t>(p)] = kRequired;
    warm_rows = {hint.active.begin(), hint.active.end()};
  }
  clock.lap("increments: candidates");
  const bool recording = hints && hints->mode == TrialHints::Mode::record;
  std::vector<int> lcp_points;  // the last round's, when recording
  const HintRecorder recorder{recording ? hints : nullptr, lcp_points, warm_rows};
  const auto held = [&](int p) {
    const YieldPoint& point = ctx.points[p];
    return solvers.condensed && solvers.condensed->covers(point.block_i) &&
           (point.block_j == kGround || solvers.condensed->covers(point.block_j));
  };
  const auto in_lcp = [&](int p) {
    return candidate[p] == kRequired ||
           ((candidate[p] == kNear || candidate[p] == kAround) && held(p));
  };
  // Points found violated (by a round's check, or by an iterate's) are required in the next
  // round. The flow spreads further: for each one that was outside the LCP, at most
  // kNearPerReached of the points this round's plastic flow moved towards yield (f -
  // f_predicted, the change the elastic predictor did not foresee) join it where that change,
  // candidate_margin times over, reaches yield. Returns how many were outside.
  const auto require = [&](const std::vector<int>& violated, const YieldValues& f) {
    std::size_t outside = 0;
    for (int p : violated) {
      if (!in_lcp(p))
        ++outside;
      candidate[static_cast<std::size_t>(p)] = kRequired;
    }
    if (outside > 0)
      join_nearest(f, Eigen::VectorXd(f.f - predicted_f.f), tol, opt.candidate_margin,
                   kNearPerReached * outside, candidate);
    return outside;
  };
  bool on_tangent = false;  // the last round's LCP ran on the reduced tangent
  for (t.rounds = 1; t.rounds <= opt.max_rounds; ++t.rounds) {
    // The LCP in the unknowns of the zone K is condensed onto (condensed_stiffness.hpp): it
    // must hold every block the required candidates touch, and under displacement control the
    // monitor's.
    std::vector<char> needed(static_cast<std::size_t>(model.n_blocks()), 0);
    bool required = false;
    for (std::size_t p = 0; p < candidate.size(); ++p)
      if (candidate[p] == kRequired) {
        flag_blocks(ctx.points[p], needed);
        required = true;
      }
    if (required) {
      if (control)
        needed[static_cast<std::size_t>(model.monitors[ctx.stage.control->monitor].block)] = 1;
      solvers.condense(model, needed, opt);
    }
    clock.lap("increments: condensation");
    std::vector<int> candidates;
    for (std::size_t p = 0; p < candidate.size(); ++p)
      if (required && in_lcp(static_cast<int>(p)))
        candidates.push_back(static_cast<int>(p));
    if (recording)
      lcp_points = candidates;
    const YieldSystem sys = assemble_yield_system(model, ctx.points, s.points, s.u, candidates);
    clock.lap("increments: yield rows");
    const int m = sys.size();
    t.lcp_size = m;
    // solve_lcp: nu = -f0 - C dU + N lambda with dU = dfactor x_ref + K^-1 Phi lambda; under
    // displacement control dfactor = (step - h . lambda) / rate, h_r = control . K^-1 phi_r,
    // keeps the monitor on its prescribed path.
    const Eigen::VectorXd cx = sys.c * ctx.x_ref;
    const Eigen::VectorXd lcp_q = control
                                      ? Eigen::VectorXd(-sys.f0 - cx * (step / ctx.control_rate))
                                      : Eigen::VectorXd(-sys.f0 - cx * step);
    // The opening multiplier is the total gap z = gap_old + lambda (it may close again).
    Eigen::VectorXd gap_old = Eigen::VectorXd::Zero(m);
    Eigen::VectorXd warm = Eigen::VectorXd::Zero(m);
    for (int r = 0; r < m; ++r) {
      const YieldRow& row = sys.rows[r];
      if (ctx.points[row.point].is_interface() && row.mode == kOpeningMode)
        gap_old(r) = s.points[row.point].gap;
      if (gap_old(r) > 0.0 || warm_rows.count({row.point, row.mode}))
        warm(r) = 1.0;
    }
    Eigen::VectorXd z = Eigen::VectorXd::Zero(m);
    std::optional<Eigen::VectorXd> plastic_du;  // K^-1 Phi (z - gap_old), once known
    if (m > 0) {
      const CondensedStiffness& condensed = *solvers.condensed;
      const YieldSystem local = condensed.local(sys);
      const Eigen::VectorXd local_control =
          control ? condensed.local(ctx.control) : Eigen::VectorXd();
      FlexibilityColumns& columns = *solvers.columns;
      const double solved_before = columns.seconds();
      IncrementLcp lcp(local, ctx.points, columns, lcp_q, gap_old,
                       control ? &local_control : nullptr,
                       control ? Eigen::VectorXd(cx / ctx.control_rate) : Eigen::VectorXd());
      clock.lap("increments: LCP matrix", "increments: K^-1 Phi columns",
                columns.seconds() - solved_before);
      // solve_lcp: the active-set method first (warm-started from the rows that yielded in the
      // last increment and the open joints), on the sparse reduced tangent when many rows are
      // active, else on the dense active block (only the columns of active rows are formed);
      // where it does not converge, Lemke on a working set, then on the whole matrix. A
      // collapse is a Lemke ray or a Farkas certificate (docs/formulation.md).
      const double columns_before = columns.seconds();
      LcpResult r;
      const Eigen::VectorXd* warm_start = warm.maxCoeff() > 0.0 ? &warm : nullptr;
      const bool tangent_route = opt.active_set && opt.reduced_tangent_rows >= 0 &&
                                 warm.sum() >= opt.reduced_tangent_rows && !control;
      on_tangent = tangent_route;
      if (tangent_route) {
        // Many rows active: the equations of each active set on the sparse reduced tangent.
        // It reads no column of K^-1 Phi: those kept go, to make room for its factor (they
        // are formed again if the dense route is ever needed).
        columns.clear();
        SplitLcp split{&condensed.lower(), &local.c, &local.phi, &local.n, lcp.q(), {}, {}};
        for (int i = 0; i < m; ++i) {
          split.group.push_back(lcp.group(i));
          split.group_rank.push_back(lcp.group_rank(i));
        }
        // Symmetric (associated flow): Cholesky, with the kept factor's updates; else LU.
        std::unique_ptr<ActiveSetEquations> equations;
        if (lcp.symmetric())
          equations = std::make_unique<ReducedTangentEquations>(split, condensed.factor(),
                                                                *solvers.tangent);
        else
          equations = std::make_unique<UnsymmetricTangentEquations>(split, condensed.factor());
        // Near a collapse, projected Newton can take many steps on a round's LCP that lacks the
        // points of the mechanism. After PlasticOptions::interrupt_after steps each iterate is
        // checked on every point, and points outside the LCP that it violates end the round at
        // once: the next round holds them. The last round is always solved and checked whole.
        std::vector<int> outside;  // points outside the LCP that the iterate violates
        YieldValues f_iterate;
        int stalled = 0;  // iterates shown to the interrupt
        const ActiveSetLcp::Interrupt interrupt = [&](const LcpResult& iterate) {
          AnalysisState at = s;  // load control: the tangent route's
          const Eigen::VectorXd lambda = iterate.z - gap_old;
          at.u += step * ctx.x_ref + ctx.k.solve(Eigen::VectorXd(sys.phi * lambda));
          update_state(sys, lambda, iterate.z, ctx.points, at);
          std::vector<int> violators;
          check_all_yield_functions(ctx, at, tol, violators, f_iterate);
          outside.clear();
          for (int p : violators)
            if (!in_lcp(p))
              outside.push_back(p);
          // A round that stalls on the points around the flow, twice as long, goes on without
          // them: past a collapse the larger LCP can leave projected Newton lowering its
          // objective without end, where the smaller one's rounds find the mechanism's
          // certificate.
          return !outside.empty() || (around && ++stalled > opt.interrupt_after);
        };
        r = solvers.active_set.solve(*equations, warm_start, &interrupt);
        t.active_set_iterations += r.steps;
        t.tangent_factorizations += equations->factorizations();
        if (std::getenv("BIMROCK_DEBUG_LCP") && r.status != LcpStatus::solved)
          std::fprintf(stderr, "reduced tangent m=%d: %s after %d, worst residual %g\n", m,
                       to_string(r.status), r.steps, r.residuals.worst_relative());
        // A round on the points around the flow that ends unsolved (at the iteration limit, or
        // where no step lowers the objective) goes on without them too, as a stalled one does.
        const bool unsolved_around =
            around && r.z.size() == m &&
            (r.status == LcpStatus::iteration_limit || r.status == LcpStatus::numerical_failure);
        if (r.status == LcpStatus::interrupted || unsolved_around) {
          ++solvers.interrupted_rounds;
          clock.lap("increments: LCP", "increments: K^-1 Phi columns",
                    columns.seconds() - columns_before);
          // The next round starts from the iterate's active rows and the modes it violates.
          if (outside.empty()) {  // it stalled on the points around the flow
            std::replace(candidate.begin(), candidate.end(), kAround, kNone);
            around = false;
            ++solvers.rounds_without_around;
          }
          require(outside, f_iterate);
          warm_rows = active_rows(sys, r.z, gap_old);
          add_violated_modes(outside, f_iterate, tol, warm_rows);
          continue;
        }
      }
      if (tangent_route && m > opt.dense_fallback_rows && r.status != LcpStatus::solved &&
          r.status != LcpStatus::no_solution) {
        t.status = Trial::Status::failed;  // too large for the dense route: cut the step
        return t;
      }
      if (opt.active_set && r.status != LcpStatus::solved && r.status != LcpStatus::no_solution) {
        r = solvers.active_set.solve(lcp, warm_start);
        t.active_set_iterations += r.steps;
      }
      if (opt.active_set && r.status != LcpStatus::solved && r.status != LcpStatus::no_solution) {
        if (std::getenv("BIMROCK_DEBUG_LCP"))
          std::fprintf(stderr, "active set m=%d: %s after %d, worst residual %g\n", m,
                       to_string(r.status), r.steps, r.residuals.worst_relative());
        // Lemke on the rows that were violated or active (and those its solution violates):
        // the columns of the other rows are never formed.
        std::vector<Eigen::Index> initial;
        for (int i = 0; i < m; ++i)
          if (warm(i) > 0.0 || (r.z.size() == m && r.z(i) > 0.0))
            initial.push_back(i);
        r = solve_on_working_set(lcp, initial, solvers.lemke);
        t.pivots += r.steps;
        if (std::getenv("BIMROCK_DEBUG_LCP"))
          std::fprintf(stderr, "  working set of %zu rows first: %s, %d pivots\n", initial.size(),
                       to_string(r.status), r.steps);
      }
      if (r.status != LcpStatus::solved && r.status != LcpStatus::no_solution) {
        // Lemke on the whole matrix, then the complete method: Lemke decides an LCP only for
        // copositive-plus M, and on the degenerate LCPs of cohesionless joints and of
        // non-associated flow it can end on a ray that proves nothing. Branch and bound on the
        // pairs decides every LCP: a solution, or a proof that there is none.
        const LcpProblem dense = lcp.dense();
        r = solvers.lemke.solve(dense);
        t.pivots += r.steps;
        if (r.status != LcpStatus::solved && r.status != LcpStatus::no_solution) {
          r = solvers.complete.solve(dense);
          if (std::getenv("BIMROCK_DEBUG_LCP"))
            std::fprintf(stderr, "  branch and bound on %d rows: %s, %d nodes\n", m,
                         to_string(r.status), r.steps);
        }
      }
      clock.lap("increments: LCP", "increments: K^-1 Phi columns",
                columns.seconds() - columns_before);
      if (r.status == LcpStatus::no_solution) {
        t.status = Trial::Status::collapse;
        t.rows = sys.rows;
        if (r.ray.size() == m) {
          t.ray = r.ray;
          t.du = ctx.k.solve(Eigen::VectorXd(sys.phi * r.ray));
          // Under load control q moves with the step and M does not: the ray proves every
          // step from some fraction of this one on (a tighter upper bound for the bracket).
          if (!control)
            t.proven_fraction = certified_from(lcp.q(), Eigen::VectorXd(-cx * step), r.ray);
        }
        return t;
      }
      if (r.status == LcpStatus::solved && !control) {
        // A mechanism that round-off turned into a very soft mode: with stiff (penalty)
        // interfaces K^-1 is accurate only to ~ penalty x machine precision, so the exact null
        // direction of M (e.g. all blocks flowing plastically together) appears as a tiny
        // positive eigenvalue and the multipliers blow up instead of Lemke finding a ray.
        // Plastic displacements that dwarf the elastic ones of the same step are that mechanism.
        const Eigen::VectorXd flow = r.z - gap_old;
        plastic_du = ctx.k.solve(Eigen::VectorXd(sys.phi * flow));
        const double plastic = plastic_du->cwiseAbs().maxCoeff();
        const double elastic = std::abs(step) * ctx.x_ref.cwiseAbs().maxCoeff();
        if (plastic > kMechanismRatio * elastic) {
          t.status = Trial::Status::collapse;
          t.rows = sys.rows;
          t.ray = flow.cwiseAbs() / flow.cwiseAbs().maxCoeff();
          t.du = *plastic_du / flow.cwiseAbs().maxCoeff();
          return t;
        }
      }
      if (r.status != LcpStatus::solved) {
        if (std::getenv("BIMROCK_DEBUG_LCP"))
          std::fprintf(stderr, "LCP m=%d step=%g: %s, worst residual %g\n", m, step,
                       to_string(r.status), r.residuals.worst_relative());
        if (std::getenv("BIMROCK_DEBUG_LCP_DUMP")) {
          std::ofstream dump(std::getenv("BIMROCK_DEBUG_LCP_DUMP"));
          write_lcp(dump, lcp.dense());
        }
        t.status = Trial::Status::failed;
        return t;
      }
      z = r.z;
    }
    const Eigen::VectorXd lambda = z - gap_old;
    if (!plastic_du)  // the displacements of the whole model: a solve with K's factor
      plastic_du = m > 0 ? ctx.k.solve(Eigen::VectorXd(sys.phi * lambda))
                         : Eigen::VectorXd::Zero(model.n_dofs());
    const double dfactor =
        control ? (step - ctx.control.dot(*plastic_du)) / ctx.control_rate : step;
    t.du = dfactor * ctx.x_ref + *plastic_du;
    t.next = s;
    t.next.u += t.du;
    t.next.stage_factor += dfactor;
    update_state(sys, lambda, z, ctx.points, t.next);
    // check_all_yield_functions: add the violated points that were not in the LCP.
    std::vector<int> violators;
    YieldValues f_next;
    check_all_yield_functions(ctx, t.next, tol, violators, f_next);
    clock.lap("increments: update and check");
    const std::size_t added = require(violators, f_next);
    // The next round, if any, starts from this one's active rows and the modes the check found
    // violated (10^4 blocks: LCP 3.64 -> 3.35 s against its first solve finding them).
    warm_rows = active_rows(sys, z, gap_old);
    if (added > 0)
      add_violated_modes(violators, f_next, tol, warm_rows);
    if (added == 0) {
      solvers.last_active = warm_rows;
      solvers.last_on_tangent = on_tangent;
      t.rows = sys.rows;
      t.lambda = lambda;
      t.status = Trial::Status::carried;
      t.kink = first_kink(model, ctx.points, s, t.next);
      return t;
    }
  }
  t.status = Trial::Status::failed;
  return t;
}

IncrementRecord record(const Model& model, const Trial& t, int stage, int increment,
                       double seconds) {
  IncrementRecord r;
  r.stage = stage;
  r.increment = increment;
  r.stage_factor = t.next.stage_factor;
  for (const Monitor& m : model.monitors)
    r.monitors.push_back(displacement_at(model, m.block, m.point, t.next.u));
  std::vector<char> yielded(t.next.points.size(), 0);
  for (std::size_t k = 0; k < t.rows.size(); ++k)
    if (std::abs(t.lambda(static_cast<Eigen::Index>(k))) > 0.0)
      yielded[t.rows[k].point] = 1;
  for (std::size_t p = 0; p < yielded.size(); ++p) {
    r.yielding_points += yielded[p];
    r.open_points += t.next.points[p].gap > 0.0 ? 1 : 0;
  }
  r.lcp_size = t.lcp_size;
  r.pivots = t.pivots;
  r.active_set_iterations = t.active_set_iterations;
  r.tangent_factorizations = t.tangent_factorizations;
  r.rounds = t.rounds;
  r.seconds = seconds;
  return r;
}

// The mechanism: the ray of the failed step where Lemke found one, else the flow of the last
// carried step (near collapse it is dominated by the mechanism).
Collapse describe_collapse(int stage, double carried, double failed, const Trial* failure,
                           const Trial* last) {
  Collapse c{stage, carried, failed, {}, {}};
  const Trial* source = failure && failure->ray.size() > 0 ? failure : last;
  if (!source || source->rows.empty())
    return c;
  const Eigen::VectorXd& flow = source == failure ? failure->ray : last->lambda;
  const double top = flow.cwiseAbs().maxCoeff();
  for (std::size_t k = 0; k < source->rows.size(); ++k) {
    const double l = flow(static_cast<Eigen::Index>(k));
    if (top > 0.0 && std::abs(l) > 1e-3 * top)
      c.mechanism.push_back({source->rows[k].point, source->rows[k].mode, l / top});
  }
  const double norm = source->du.norm();
  if (norm > 0.0)
    c.direction = source->du / norm;
  return c;
}

}  // namespace

// The result, with where the LCP phase's time went: the tangent's factorizations and solves,
// and the solves with K (flexibility columns, and every LCP result measured).
PlasticResult with_solver_work(PlasticResult result, const SparseCholesky& k,
                               const LcpSolvers& solvers) {
  CholeskyWork tangent = solvers.retired_tangent;
  if (solvers.tangent)
    LcpSolvers::add(tangent, solvers.tangent->cholesky.work());
  CholeskyWork s = solvers.retired_s;
  if (solvers.condensed && !solvers.condensed->whole())
    LcpSolvers::add(s, solvers.condensed->factor().work());
  result.timings.add("(LCP: tangent factorizations)", tangent.factorize_seconds);
  result.timings.add("(LCP: tangent solves)", tangent.solve_seconds);
  result.timings.add("(solves with K)", k.work().solve_seconds);
  result.timings.add("(solves with S, K condensed)", s.solve_seconds);
  result.condensations = solvers.condensations;
  result.reserve_switches = solvers.reserve_switches;
  result.regions = solvers.regions;
  result.interrupted_rounds = solvers.interrupted_rounds;
  result.rounds_without_around = solvers.rounds_without_around;
  result.zone_blocks = solvers.condensed ? solvers.condensed->zone_blocks() : 0;
  return result;
}

PlasticResult run_plastic_analysis(const Model& model, const PlasticOptions& opt,
                                   const IncrementCallback& on_increment) {
  const KeptFactorMemoryRelease release_at_end;  // declared first: runs after the factors go
  PlasticResult result;
  result.timings.track_memory = opt.track_memory;
  {
    ScopedTimer t(result.timings, "check supports");
    check_supports(model);
  }
  SparseCholesky k;
  SparseMatrix lower;  // kept: the reduced tangent is K minus the plastic part
  {
    {
      ScopedTimer t(result.timings, "assemble");
      lower = assemble_stiffness_lower(model);
    }
    ScopedTimer f(result.timings, "factorize");
    k.analyze(lower, 6);
    if (!k.factorize(lower))
      report_singular_stiffness(model, k.failed_column());
  }
  result.points = make_yield_points(model);
  result.state.u = Eigen::VectorXd::Zero(model.n_dofs());
  result.state.points.assign(result.points.size(), PlasticState{});
  LcpSolvers solvers(k, lower, opt);
  if (opt.hints && opt.hints->mode == TrialHints::Mode::replay) {
    // The oracle's one zone, condensed onto at the start: every block a recorded LCP touches.
    ScopedTimer t(result.timings, "increments: condensation");
    opt.hints->next = 0;
    std::vector<char> touched(static_cast<std::size_t>(model.n_blocks()), 0);
    for (const TrialHint& h : opt.hints->trials)
      for (int p : h.points) {
        if (p < 0 || static_cast<std::size_t>(p) >= result.points.size())
          throw std::invalid_argument("plastic analysis: trial hints of another model");
        flag_blocks(result.points[static_cast<std::size_t>(p)], touched);
      }
    if (std::find(touched.begin(), touched.end(), 1) != touched.end())
      solvers.condense(model, touched, opt);
  }
  const YieldEvaluator yield(model, result.points);
  for (int st = 0; st < static_cast<int>(model.stages.size()); ++st) {
    const Stage& stage = model.stages[st];
    StageContext ctx{model, result.points, k, stage, yield, {}, {}, 0.0, &result.timings};
    {
      ScopedTimer t(result.timings, "stage loads");
      ctx.x_ref = k.solve(assemble_loads(model, stage.loads));
    }
    double step = 1.0 / stage.increments;
    if (stage.control) {
      const Monitor& m = model.monitors[stage.control->monitor];
      ctx.control = Eigen::VectorXd::Zero(model.n_dofs());
      ctx.control.segment<6>(6 * m.block) =
          block_Q(model.blocks[m.block].centroid, m.point).transpose() * stage.control->direction;
      ctx.control_rate = ctx.control.dot(ctx.x_ref);
      if (!(std::abs(ctx.control_rate) > 0.0))
        throw ModelError("stage '" + stage.name + "': the controlled monitor '" + m.name +
                             "' does not move under the stage's loads",
                         {m.block});
      step = stage.control->displacement / stage.increments;
    }
    result.state.stage_factor = 0.0;
    std::optional<Trial> last;
    int increment = 0;
    for (int n = 0; n < stage.increments; ++n) {
      auto part_start = std::chrono::steady_clock::now();
      // Records a carried trial (a whole increment or one part of it) with the time since the
      // last part: the parts' times add up, none counts another's (nor the callback's).
      auto finish = [&](const Trial& carried) {
        const double secs =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - part_start).count();
        result.state = carried.next;
        result.history.push_back(record(model, carried, st, ++increment, secs));
        if (on_increment)
          on_increment(result.history.back(), result.state);
        last = carried;
        part_start = std::chrono::steady_clock::now();
      };
      Trial t = try_increment(ctx, result.state, step, opt, solvers);
      // A softening law that reaches its residual value inside the step: stop the step there
      // and carry the rest as a further step (the laws are linear on each side of the kink).
      double rest = step;
      for (int cuts = 0; cuts < 100 && t.status == Trial::Status::carried && t.kink < 1.0; ++cuts) {
        const Trial to_kink = try_increment(ctx, result.state, t.kink * rest, opt, solvers);
        if (to_kink.status != Trial::Status::carried)
          break;
        const double done = to_kink.next.stage_factor - result.state.stage_factor;
        finish(to_kink);
        rest = stage.control ? rest * (1.0 - t.kink) : rest - done;
        t = try_increment(ctx, result.state, rest, opt, solvers);
      }
      if (t.status == Trial::Status::carried) {
        finish(t);
        continue;
      }
      // Bisect the failed step: carry what can be carried, bracket the collapse load. The
      // bracket's upper end is the nearest load proven to fail (by a ray, which proves every
      // step from a fraction of the failed one on: certified_from()). A step that fails only
      // numerically (close to the collapse, where the LCP is nearly singular, or a large step
      // whose active set the solvers did not find) proves nothing: it is cut, and once a part
      // of it has carried the rest of the increment is tried again from the new state
      // (docs/formulation.md).
      double carried = result.state.stage_factor;
      double remaining = rest;       // of this increment, in the units of `step`
      double failing_step = rest;    // from the state: proven to fail, or the last that failed
      std::optional<double> proven;  // stage factor of the nearest ray
      Trial failure = t;
      // A certificate's bound is often the collapse load itself (its mechanism is the one that
      // forms): the trials aim near it, where halving would take ~log2(gap / tolerance) carried
      // trials, until one of them fails.
      bool aim = false;
      bool retry = false;  // a numerical failure, then a carried part: try the rest again
      if (t.status == Trial::Status::collapse) {
        failing_step *= t.proven_fraction;
        proven = carried + failing_step;
        aim = t.proven_fraction < 1.0;
      }
      // A structure proven to fail within the bracket tolerance of its first load, with nothing
      // carried, is unstable under that load: bisecting towards zero load would only bracket
      // round-off.
      const auto unstable_at_start = [&] {
        return st == 0 && result.history.empty() && proven && *proven <= opt.bracket_tolerance;
      };
      for (int b = 0; b < opt.max_bisections && remaining > 0.0 && !unstable_at_start(); ++b) {
        const double upper = proven ? *proven : carried + failing_step;
        if (std::abs(upper - carried) <= opt.bracket_tolerance * std::abs(upper))
          break;
        const double trial = retry ? remaining : (aim ? kAimAtBound : 0.5) * failing_step;
        retry = false;
        const Trial half = try_increment(ctx, result.state, trial, opt, solvers);
        if (half.status == Trial::Status::carried) {
          finish(half);
          carried = result.state.stage_factor;
          remaining = trial == remaining ? 0.0 : remaining - trial;
          if (proven) {
            failing_step = *proven - carried;
          } else {
            failing_step -= trial;
            retry = true;
          }
        } else if (half.status == Trial::Status::collapse) {
          proven = carried + trial * half.proven_fraction;
          failing_step = *proven - carried;
          failure = half;
          aim = false;
        } else {
          failing_step = trial;
          aim = false;
        }
      }
      if (!proven && remaining == 0.0)
        continue;  // the increment is carried in parts: go on with the next
      if (!proven) {
        // Neither carried nor proven to fail: near a limit load the LCP is nearly singular.
        // Stop here, honestly, with every carried increment kept; not a collapse.
        // What the user can do: displacement control passes a limit point that load control
        // cannot prove.
        const std::string what_to_try =
            stage.control ? "; try more increments in this stage"
                          : "; to pass a limit load, prescribe a monitor's displacement in this "
                            "stage instead (stages[].control, docs/case-file.md)";
        result.stopped = Stop{st, carried,
                              "the increment after stage factor " + std::to_string(carried) +
                                  " could not be solved accurately, nor shown to have no "
                                  "solution (the structure is close to a limit load)" +
                                  what_to_try};
        return with_solver_work(std::move(result), k, solvers);
      }
      result.collapse = describe_collapse(st, carried, *proven, &failure, last ? &*last : nullptr);
      result.collapse->unstable_at_first_load = unstable_at_start();
      return with_solver_work(std::move(result), k, solvers);
    }
  }
  return with_solver_work(std::move(result), k, solvers);
}

}  // namespace bimrock
