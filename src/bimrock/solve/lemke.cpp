#include <bimrock/solve/lemke.hpp>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <utility>
#include <vector>

#include <Eigen/LU>

namespace bimrock {
namespace {

using Index = Eigen::Index;

/// Ratios within this fraction of the smallest are ties, resolved lexicographically.
constexpr double kTie = 1e-12;
/// The values compared are in units of max|q^| = 1. Below this size a difference is round-off
/// (kTie * kTieFloor ~ 1e-16); above it ties are relative: rows of q near yield can be 1e-13 of
/// the largest and still differ (measured on an LCP recorded at a sliding collapse, where an
/// absolute tie of 1e-12 chose the wrong leaving row and ended on an infeasible basis).
constexpr double kTieFloor = 1e-4;

/// The problem Lemke pivots on: M^ = R M C (round-off entries removed), q^ = R q / sigma and the
/// covering vector e^, so that z = sigma C z^ and the LCP is unchanged (positive diagonal
/// scalings preserve z >= 0, w >= 0, z . w = 0).
struct ScaledProblem {
  Eigen::MatrixXd m;
  Eigen::VectorXd q;
  Eigen::VectorXd e;
  Eigen::VectorXd row;  ///< R
  Eigen::VectorXd col;  ///< C
  double sigma = 1.0;
};

/// The nearest power of two, so that scaling by it is exact.
double power_of_two(double f) {
  return std::exp2(std::round(std::log2(f)));
}

/// Ruiz's equilibration (2001): divide every row and column by the square root of its largest
/// entry until all are near 1. Zero rows and columns keep the factor 1.
void equilibrate(const Eigen::MatrixXd& m, Eigen::VectorXd& row, Eigen::VectorXd& col) {
  for (int sweep = 0; sweep < 30; ++sweep) {
    const Eigen::MatrixXd a = (row.asDiagonal() * m * col.asDiagonal()).cwiseAbs();
    const Eigen::VectorXd row_max = a.rowwise().maxCoeff();
    const Eigen::VectorXd col_max = a.colwise().maxCoeff().transpose();
    bool changed = false;
    for (Index i = 0; i < m.rows(); ++i) {
      const double fr = row_max(i) > 0.0 ? power_of_two(1.0 / std::sqrt(row_max(i))) : 1.0;
      const double fc = col_max(i) > 0.0 ? power_of_two(1.0 / std::sqrt(col_max(i))) : 1.0;
      changed = changed || fr != 1.0 || fc != 1.0;
      row(i) *= fr;
      col(i) *= fc;
    }
    if (!changed)
      return;
  }
}

ScaledProblem scale(const LcpProblem& p, const LemkeOptions& o) {
  const Index n = p.size();
  ScaledProblem s;
  const double m_max = p.m.cwiseAbs().maxCoeff();
  s.m = (p.m.array().abs() > o.zero_tolerance * m_max).select(p.m, 0.0);
  s.row = Eigen::VectorXd::Ones(n);
  s.col = Eigen::VectorXd::Ones(n);
  if (o.equilibrate)
    equilibrate(s.m, s.row, s.col);
  s.m = s.row.asDiagonal() * s.m * s.col.asDiagonal();
  s.q = s.row.cwiseProduct(p.q);
  s.sigma = s.q.cwiseAbs().maxCoeff();  // > 0: some q_i < 0
  s.q /= s.sigma;
  if (o.covering.size() == 0) {
    s.e = Eigen::VectorXd::Ones(n);
  } else {
    if (o.covering.size() != n || !(o.covering.array() > 0.0).all()) {
      throw std::invalid_argument("Lemke: the covering vector must be positive and of size n");
    }
    s.e = s.row.cwiseProduct(o.covering);
    s.e /= s.e.maxCoeff();
  }
  return s;
}

/// B^-1 of a basis that Lemke's pivots reached from the identity (every w basic). A pivot on
/// row r is a row operation: every row gains a multiple of row r. So B^-1 stays the identity
/// but in the columns of the rows pivoted on so far, which are kept dense: n x (those rows), not
/// n x n, and each pivot and each product with B^-1 costs that much. (The rows pivoted on are a
/// fraction of n: on the LCPs of 2 600 rows of a non-associated collapse, Lemke's pivots and
/// column products were half of the analysis with the whole n x n inverse.)
class BasisInverse {
 public:
  explicit BasisInverse(Index n) : n_(n), slot_(static_cast<std::size_t>(n), -1) {}

  [[nodiscard]] double operator()(Index i, Index j) const {
    const Index s = slot_[static_cast<std::size_t>(j)];
    return s < 0 ? (i == j ? 1.0 : 0.0) : dense_(i, s);
  }
  [[nodiscard]] Eigen::VectorXd col(Index j) const {
    const Index s = slot_[static_cast<std::size_t>(j)];
    return s < 0 ? Eigen::VectorXd(Eigen::VectorXd::Unit(n_, j)) : Eigen::VectorXd(dense_.col(s));
  }
  /// B^-1 a: a on the identity's columns, the dense columns' combination on the others.
  [[nodiscard]] Eigen::VectorXd times(const Eigen::VectorXd& a) const {
    Eigen::VectorXd y = a;
    Eigen::VectorXd on_dense(columns());
    for (Index s = 0; s < columns(); ++s) {
      const Index j = pivoted_[static_cast<std::size_t>(s)];
      on_dense(s) = a(j);
      y(j) = 0.0;
    }
    y.noalias() += dense_.leftCols(columns()) * on_dense;
    return y;
  }
  /// |B^-1_i.|_1
  [[nodiscard]] double row_norm(Index i) const {
    const double own = slot_[static_cast<std::size_t>(i)] < 0 ? 1.0 : 0.0;
    return own + dense_.row(i).head(columns()).lpNorm<1>();
  }
  /// The row operation that makes the column d the unit vector e_r.
  void pivot(Index r, const Eigen::VectorXd& d) {
    make_dense(r);
    const Index k = columns();
    const Eigen::RowVectorXd pivot_row = dense_.row(r).head(k) / d(r);
    Eigen::VectorXd f = d;
    f(r) = 0.0;
    dense_.leftCols(k).noalias() -= f * pivot_row;
    dense_.row(r).head(k) = pivot_row;
  }

 private:
  [[nodiscard]] Index columns() const { return static_cast<Index>(pivoted_.size()); }
  // Column r kept dense from now on (its identity column, e_r, to start with).
  void make_dense(Index r) {
    if (slot_[static_cast<std::size_t>(r)] >= 0)
      return;
    const Index k = columns();
    if (k == dense_.cols())
      dense_.conservativeResize(n_, std::min(n_, std::max<Index>(16, 2 * k)));
    dense_.col(k) = Eigen::VectorXd::Unit(n_, r);
    slot_[static_cast<std::size_t>(r)] = k;
    pivoted_.push_back(r);
  }

  Index n_;
  Eigen::MatrixXd dense_;       // n x (capacity); its first columns() are in use
  std::vector<Index> slot_;     // per column of B^-1, its column in dense_ (-1: the identity's)
  std::vector<Index> pivoted_;  // per column of dense_, the column of B^-1 it holds
};

/// A basis of  I w - M^ z - e^ z0 = q^  over the variables w_i = i, z_i = n + i, z0 = 2n:
/// B^-1 and the basic values x = B^-1 q^. The rows of [x, B^-1] are the lexicographic keys.
struct Tableau {
  const ScaledProblem& p;
  Index n;
  BasisInverse binv;
  Eigen::VectorXd x;
  std::vector<Index> basic;   ///< variable of each row
  std::vector<Index> row_of;  ///< row of each variable, -1 when nonbasic

  explicit Tableau(const ScaledProblem& problem)
      : p(problem),
        n(problem.q.size()),
        binv(n),
        x(problem.q),
        basic(static_cast<std::size_t>(n)),
        row_of(static_cast<std::size_t>(2 * n + 1), -1) {
    std::iota(basic.begin(), basic.end(), Index{0});
    std::iota(row_of.begin(), row_of.begin() + n, Index{0});
  }
  [[nodiscard]] Index z0() const { return 2 * n; }
  [[nodiscard]] Index complement(Index var) const { return var < n ? var + n : var - n; }

  /// d = B^-1 a for the column a of the variable: e_i for w_i, -M^_i for z_i, -e^ for z0.
  [[nodiscard]] Eigen::VectorXd column(Index var) const {
    if (var < n)
      return binv.col(var);
    if (var < 2 * n)
      return -binv.times(p.m.col(var - n));
    return -binv.times(p.e);
  }
  [[nodiscard]] double column_scale(Index var) const {
    if (var < n)
      return 1.0;
    if (var < 2 * n)
      return p.m.col(var - n).cwiseAbs().maxCoeff();
    return p.e.cwiseAbs().maxCoeff();
  }

  /// Exchanges the basic variable of row r for `entering`, whose column is d (rank-1 update).
  void pivot(Index r, Index entering, const Eigen::VectorXd& d) {
    binv.pivot(r, d);
    x(r) /= d(r);
    Eigen::VectorXd f = d;
    f(r) = 0.0;
    x -= f * x(r);
    row_of[static_cast<std::size_t>(basic[static_cast<std::size_t>(r)])] = -1;
    basic[static_cast<std::size_t>(r)] = entering;
    row_of[static_cast<std::size_t>(entering)] = r;
  }

  [[nodiscard]] Index row_of_var(Index var) const { return row_of[static_cast<std::size_t>(var)]; }
};

/// Among `rows`, the one whose key (B^-1_i.) / divisor_i is lexicographically smallest; the
/// first component x_i / divisor_i is compared too when `with_x`. Ties that survive every
/// column (only possible through round-off) go to the largest divisor, the safest pivot.
Index lexico_min(const Tableau& t, std::vector<Index> rows, const Eigen::VectorXd& divisor,
                 bool with_x) {
  for (Index k = with_x ? -1 : 0; k < t.n && rows.size() > 1; ++k) {
    auto key = [&](Index i) { return (k < 0 ? t.x(i) : t.binv(i, k)) / divisor(i); };
    double lo = key(rows.front());
    double size = 0.0;
    for (Index i : rows) {
      lo = std::min(lo, key(i));
      size = std::max(size, std::abs(key(i)));
    }
    const double scale = k < 0 ? std::max(std::abs(lo), kTieFloor) : std::max(1.0, size);
    std::erase_if(rows, [&](Index i) { return key(i) > lo + kTie * scale; });
  }
  return *std::max_element(rows.begin(), rows.end(),
                           [&](Index a, Index b) { return divisor(a) < divisor(b); });
}

/// The minimum-ratio rows for the entering column d: significant positive d_i (above the
/// round-off bound pivot_tolerance * |B^-1_i.|_1 * |a|_inf) with the smallest x_i / d_i, ties
/// included. Empty means a secondary ray.
std::vector<Index> min_ratio_rows(const Tableau& t, const Eigen::VectorXd& d, double a_scale,
                                  double pivot_tolerance) {
  std::vector<std::pair<double, Index>> by_ratio;
  for (Index i = 0; i < t.n; ++i) {
    if (d(i) > 0.0)
      by_ratio.emplace_back(std::max(t.x(i), 0.0) / d(i), i);
  }
  std::sort(by_ratio.begin(), by_ratio.end());
  std::vector<Index> ties;
  double theta_min = 0.0;
  for (const auto& [theta, i] : by_ratio) {
    if (!ties.empty() && theta > theta_min + kTie * std::max(kTieFloor, theta_min))
      break;
    if (d(i) <= pivot_tolerance * t.binv.row_norm(i) * a_scale)
      continue;  // round-off
    if (ties.empty())
      theta_min = theta;
    ties.push_back(i);
  }
  return ties;
}

/// z = sigma C z^ from the basic values (nonbasic z are 0).
Eigen::VectorXd unscaled_z(const Tableau& t) {
  Eigen::VectorXd z = Eigen::VectorXd::Zero(t.n);
  for (Index j = 0; j < t.n; ++j) {
    const Index r = t.row_of_var(t.n + j);
    if (r >= 0)
      z(j) = t.p.sigma * t.p.col(j) * std::max(t.x(r), 0.0);
  }
  return z;
}

/// The z part of the secondary ray: the entering variable grows at rate 1, basic ones at -d_i.
Eigen::VectorXd ray_direction(const Tableau& t, Index entering, const Eigen::VectorXd& d) {
  Eigen::VectorXd r = Eigen::VectorXd::Zero(t.n);
  for (Index j = 0; j < t.n; ++j) {
    const Index row = t.row_of_var(t.n + j);
    const double rate = t.n + j == entering ? 1.0 : row >= 0 ? std::max(-d(row), 0.0) : 0.0;
    r(j) = t.p.col(j) * rate;
  }
  const double size = r.maxCoeff();
  return size > 0.0 ? Eigen::VectorXd(r / size) : Eigen::VectorXd();
}

/// Whether r certifies that the LCP has no solution (see lcp.hpp).
bool certifies_infeasibility(const LcpProblem& p, const Eigen::VectorXd& r) {
  return r.size() == p.size() &&
         bimrock::certifies_infeasibility(p.q, r, p.m.transpose() * r,
                                          p.m.cwiseAbs().transpose() * r.cwiseAbs(),
                                          p.m.cwiseAbs().maxCoeff());
}

/// Solves the active set of the final basis again from the unscaled M and checks the result
/// (see the file comment). The LU is of R M_AA C, the exactly scaled unscaled block.
LcpResult polish(const LcpProblem& p, const ScaledProblem& s, const Tableau& t, int pivots,
                 const LemkeOptions& o) {
  std::vector<Index> active;
  for (Index j = 0; j < t.n; ++j) {
    if (t.row_of_var(t.n + j) >= 0)
      active.push_back(j);
  }
  const auto k = static_cast<Index>(active.size());
  Eigen::MatrixXd a(k, k);
  for (Index i = 0; i < k; ++i) {
    for (Index j = 0; j < k; ++j) {
      const Index ai = active[static_cast<std::size_t>(i)];
      const Index aj = active[static_cast<std::size_t>(j)];
      a(i, j) = s.row(ai) * p.m(ai, aj) * s.col(aj);
    }
  }
  Eigen::FullPivLU<Eigen::MatrixXd> lu(a);
  lu.setThreshold(o.pivot_tolerance);

  std::vector<Eigen::VectorXd> candidates;
  if (lu.isInvertible()) {
    candidates.push_back(unscaled_z(t));
  } else {
    // The pivoting ended on a block that is singular but for round-off: its multipliers are
    // not to be trusted. A kernel direction that certifies infeasibility is a collapse.
    const Eigen::MatrixXd kernel = lu.kernel();
    for (Index c = 0; c < kernel.cols(); ++c) {
      for (double sign : {1.0, -1.0}) {
        Eigen::VectorXd r = Eigen::VectorXd::Zero(t.n);
        for (Index i = 0; i < k; ++i) {
          const Index ai = active[static_cast<std::size_t>(i)];
          r(ai) = sign * s.col(ai) * kernel(i, c);
        }
        if (!certifies_infeasibility(p, r))
          continue;
        LcpResult result = make_lcp_result(p, LcpStatus::no_solution, unscaled_z(t), pivots);
        result.ray = r / r.maxCoeff();
        return result;
      }
    }
  }
  // z_A = C_A y with (R M_AA C) y = -R q_A, then two steps of iterative refinement.
  Eigen::VectorXd z = Eigen::VectorXd::Zero(t.n);
  for (int step = 0; step < 3; ++step) {
    const Eigen::VectorXd w = p.m * z + p.q;
    Eigen::VectorXd rhs(k);
    for (Index i = 0; i < k; ++i) {
      const Index ai = active[static_cast<std::size_t>(i)];
      rhs(i) = -s.row(ai) * w(ai);
    }
    const Eigen::VectorXd dy = lu.solve(rhs);
    for (Index i = 0; i < k; ++i) {
      const Index ai = active[static_cast<std::size_t>(i)];
      z(ai) += s.col(ai) * dy(i);
    }
    candidates.push_back(z);
  }
  // Round-off may leave a basic multiplier that should be 0 slightly negative.
  for (Eigen::VectorXd& c : candidates) {
    const double tiny = o.accuracy * c.cwiseAbs().maxCoeff();
    c = (c.array() < 0.0 && c.array() > -tiny).select(0.0, c);
  }
  const auto best =
      std::min_element(candidates.begin(), candidates.end(), [&](const auto& u, const auto& v) {
        return measure(p, u).worst_relative() < measure(p, v).worst_relative();
      });
  LcpResult result = make_lcp_result(p, LcpStatus::solved, *best, pivots);
  if (!result.z.allFinite() || !(result.residuals.worst_relative() <= o.accuracy)) {
    result.status = LcpStatus::numerical_failure;
  }
  return result;
}

}  // namespace

LcpResult Lemke::solve(const LcpProblem& problem, const Eigen::VectorXd* /*warm_start*/) {
  check_lcp(problem);
  const Index n = problem.size();
  if ((problem.q.array() >= 0.0).all()) {  // z = 0 solves it exactly (also for n = 0)
    return make_lcp_result(problem, LcpStatus::solved, Eigen::VectorXd::Zero(n), 0);
  }
  const ScaledProblem s = scale(problem, options_);
  Tableau t(s);
  const int max_pivots =
      options_.max_pivots > 0 ? options_.max_pivots : static_cast<int>(50 * n + 100);

  // z0 enters at the value that makes w = q + e z0 >= 0: the row with the most negative
  // q_i / e_i leaves (lexicographically smallest (x_i, B^-1_i.) / e_i among ties).
  std::vector<Index> all(static_cast<std::size_t>(n));
  std::iota(all.begin(), all.end(), Index{0});
  Index r = lexico_min(t, all, s.e, true);
  Index entering = t.complement(t.basic[static_cast<std::size_t>(r)]);
  t.pivot(r, t.z0(), -s.e);
  int pivots = 1;

  while (true) {
    if (pivots >= max_pivots) {
      return make_lcp_result(problem, LcpStatus::iteration_limit, unscaled_z(t), pivots);
    }
    const Eigen::VectorXd d = t.column(entering);
    if (!d.allFinite()) {
      return make_lcp_result(problem, LcpStatus::numerical_failure, unscaled_z(t), pivots);
    }
    const std::vector<Index> ties =
        min_ratio_rows(t, d, t.column_scale(entering), options_.pivot_tolerance);
    if (ties.empty()) {  // secondary ray: the entering variable grows without bound
      // In exact arithmetic the ray proves infeasibility for copositive-plus M; in floating
      // point a column whose pivots all drowned in round-off also ends here. Only a ray that
      // certifies infeasibility on the unscaled problem is a collapse (measured: an LCP of 540
      // rows, PSD with 302 near-zero eigenvalues, ended on a ray with (M^T r)_i / (|M|^T |r|)_i
      // = 0.26 although projected Gauss-Seidel solves it).
      const Eigen::VectorXd ray = ray_direction(t, entering, d);
      const bool proven = ray.size() == n && certifies_infeasibility(problem, ray);
      LcpResult result =
          make_lcp_result(problem, proven ? LcpStatus::no_solution : LcpStatus::numerical_failure,
                          unscaled_z(t), pivots);
      result.ray = ray;
      return result;
    }
    const Index z0_row = t.row_of_var(t.z0());
    r = std::find(ties.begin(), ties.end(), z0_row) != ties.end() ? z0_row
                                                                  : lexico_min(t, ties, d, false);
    const Index leaving = t.basic[static_cast<std::size_t>(r)];
    t.pivot(r, entering, d);
    ++pivots;
    if (leaving == t.z0())
      return polish(problem, s, t, pivots, options_);
    entering = t.complement(leaving);
  }
}

}  // namespace bimrock
