#include <bimrock/solve/lcp_polyhedron.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <glpk.h>

namespace bimrock {
namespace {

using Index = Eigen::Index;

/// How far a w_i held at zero may stray from it, in the scaled units (max|M| = max|q| = 1).
constexpr double kHeldSlack = 1e-9;

/// Certificates of empty nodes kept to try on the next ones (certified_empty()).
constexpr std::size_t kKeptCertificates = 16;

/// Simplex settings: quiet, no presolve (it would discard the basis a child node starts from).
glp_smcp simplex_settings() {
  glp_smcp parm;
  glp_init_smcp(&parm);
  parm.msg_lev = GLP_MSG_OFF;
  parm.presolve = GLP_OFF;
  parm.meth = GLP_PRIMAL;
  return parm;
}

/// Pivots of one simplex attempt on an LP of n rows. A well-posed node needs a few n from a
/// fresh basis (measured: at most 11 n on LCPs of 200 - 560 rows), far fewer from its parent's;
/// past this the attempt has stalled on a degenerate vertex, where each pivot can cost several
/// refactorizations (measured: 1.5 ms a pivot on 243 rows, 25 300 pivots in one attempt).
[[nodiscard]] long attempt_pivots(Index n) {
  return std::min<long>(20 * static_cast<long>(n) + 1000, 1'000'000);
}

/// Silences GLPK's terminal output while it lives (its scaling and basis routines print
/// whatever the simplex's message level says), and restores the caller's setting.
class QuietGlpk {
 public:
  QuietGlpk() : old_(glp_term_out(GLP_OFF)) {}
  QuietGlpk(const QuietGlpk&) = delete;
  QuietGlpk& operator=(const QuietGlpk&) = delete;
  ~QuietGlpk() { glp_term_out(old_); }

 private:
  int old_;
};

/// The largest LP solved in exact rational arithmetic. The rationals of a dense LP's basis grow
/// with its size: on 18 rows glp_exact takes milliseconds, on 144 rows (a 14-block structure)
/// one call runs for minutes.
constexpr Index kExactRows = 40;

/// Solves p from its current basis by the primal simplex; where that fails (a degenerate LP
/// can stall it, or round-off spoil its basis), by the dual simplex from a fresh basis, and
/// last, on LPs of at most kExactRows rows, in exact rational arithmetic (glp_exact). Each
/// attempt stops after attempt_pivots(n), and all together after max_pivots. False if all fail.
bool simplex(glp_prob* p, Index n, long max_pivots) {
  const long start = glp_get_it_cnt(p);
  glp_smcp parm = simplex_settings();
  const auto limit = [&] {
    const long left = max_pivots - (glp_get_it_cnt(p) - start);
    parm.it_lim = static_cast<int>(std::min(attempt_pivots(n), left));
    return left > 0;
  };
  if (!limit())
    return false;
  if (glp_simplex(p, &parm) == 0)
    return true;
  if (!limit())
    return false;
  glp_adv_basis(p, 0);
  parm.meth = GLP_DUALP;
  if (glp_simplex(p, &parm) == 0)
    return true;
  if (n > kExactRows || !limit())
    return false;
  glp_std_basis(p);
  return glp_exact(p, &parm) == 0;
}

/// GLPK's problem object, released with its owner.
struct GlpProb {
  glp_prob* p = glp_create_prob();
  GlpProb() = default;
  GlpProb(const GlpProb&) = delete;
  GlpProb& operator=(const GlpProb&) = delete;
  ~GlpProb() { glp_delete_prob(p); }
};

/// Loads the dense matrix a (rows x cols) into p, whose rows and columns exist already.
void load_dense(glp_prob* p, const Eigen::MatrixXd& a) {
  std::vector<int> ia{0};
  std::vector<int> ja{0};
  std::vector<double> ar{0.0};
  for (Index j = 0; j < a.cols(); ++j)
    for (Index i = 0; i < a.rows(); ++i)
      if (a(i, j) != 0.0) {
        ia.push_back(static_cast<int>(i + 1));
        ja.push_back(static_cast<int>(j + 1));
        ar.push_back(a(i, j));
      }
  glp_load_matrix(p, static_cast<int>(ar.size() - 1), ia.data(), ja.data(), ar.data());
}

/// The duals of the phase-one objective (the sum of the bound violations of the basic
/// variables) at the final basis of a simplex that ended infeasible: pi with B^T pi = c_B,
/// c_B = +1 above an upper bound, -1 below a lower one. Where phase one ended at its optimum,
/// +-pi is a Farkas certificate of the rows; unchecked. Empty where the basis has no
/// factorization or nothing is violated.
Eigen::VectorXd phase_one_duals(glp_prob* p) {
  const int m = glp_get_num_rows(p);
  if (!glp_bf_exists(p) && glp_factorize(p) != 0)
    return {};
  std::vector<double> c(static_cast<std::size_t>(m) + 1, 0.0);  // 1-based, as GLPK's
  bool violated = false;
  for (int k = 1; k <= m; ++k) {
    const int v = glp_get_bhead(p, k);
    const bool row = v <= m;
    const int i = row ? v : v - m;
    const int type = row ? glp_get_row_type(p, i) : glp_get_col_type(p, i);
    const double x = row ? glp_get_row_prim(p, i) : glp_get_col_prim(p, i);
    const double lb = row ? glp_get_row_lb(p, i) : glp_get_col_lb(p, i);
    const double ub = row ? glp_get_row_ub(p, i) : glp_get_col_ub(p, i);
    const double tol = 1e-9 * (1.0 + std::abs(x));
    const bool has_lb = type == GLP_LO || type == GLP_DB || type == GLP_FX;
    const bool has_ub = type == GLP_UP || type == GLP_DB || type == GLP_FX;
    double& ck = c[static_cast<std::size_t>(k)];
    if (has_ub && x > ub + tol)
      ck = 1.0;
    else if (has_lb && x < lb - tol)
      ck = -1.0;
    violated = violated || ck != 0.0;
  }
  if (!violated)
    return {};
  glp_btran(p, c.data());
  return Eigen::Map<const Eigen::VectorXd>(c.data() + 1, m);
}

}  // namespace

struct LcpPolyhedron::Lp {
  GlpProb prob;
  GlpProb farkas;     ///< the Farkas system of a node (farkas()), built at its first use
  Eigen::MatrixXd m;  ///< M / max|M|
  Eigen::VectorXd q;  ///< q / max|q|
};

LcpPolyhedron::LcpPolyhedron(const LcpProblem& problem)
    : problem_(problem), lp_(std::make_unique<Lp>()) {
  const QuietGlpk quiet;
  check_lcp(problem);
  const Index n = problem.size();
  m_max_ = n > 0 ? problem.m.cwiseAbs().maxCoeff() : 1.0;
  q_max_ = n > 0 ? problem.q.cwiseAbs().maxCoeff() : 1.0;
  if (!(m_max_ > 0.0))
    m_max_ = 1.0;
  if (!(q_max_ > 0.0))
    q_max_ = 1.0;
  lp_->m = problem.m / m_max_;
  lp_->q = problem.q / q_max_;
  glp_prob* p = lp_->prob.p;
  glp_set_obj_dir(p, GLP_MIN);
  if (n == 0)
    return;
  glp_add_rows(p, static_cast<int>(n));  // row i: (M z)_i = w_i - q_i
  glp_add_cols(p, static_cast<int>(n));  // column j: z_j
  load_dense(p, lp_->m);
  // Objective: the sum of every z_j and w_i (w = M z + q, its constant dropped). Both of a
  // pair are pulled towards zero, and since only bounds change from node to node, the last
  // node's optimal basis stays dual feasible: the dual simplex goes on from it.
  const Eigen::VectorXd cost = lp_->m.colwise().sum().transpose() + Eigen::VectorXd::Ones(n);
  for (Index j = 0; j < n; ++j)
    glp_set_obj_coef(p, static_cast<int>(j + 1), cost(j));
  glp_adv_basis(p, 0);
}

LcpPolyhedron::~LcpPolyhedron() = default;

LcpPolyhedron::Vertex LcpPolyhedron::vertex(const std::vector<Fix>& fix, long max_pivots) {
  const Index n = problem_.size();
  if (static_cast<Index>(fix.size()) != n)
    throw std::invalid_argument("LcpPolyhedron: one fix per row");
  if (n == 0)
    return {Status::feasible, Eigen::VectorXd(), {}};
  const QuietGlpk quiet;
  glp_prob* p = lp_->prob.p;
  for (Index i = 0; i < n; ++i) {
    const Fix f = fix[static_cast<std::size_t>(i)];
    const int k = static_cast<int>(i + 1);
    // w_i = 0 up to kHeldSlack: the rows of one yield point are dependent, and the round-off
    // of M leaves a set of them held at zero slightly inconsistent (the simplex then calls the
    // node empty); the solution is made exact by the polish.
    glp_set_row_bnds(p, k, f == Fix::w ? GLP_DB : GLP_LO, -lp_->q(i), -lp_->q(i) + kHeldSlack);
    glp_set_col_bnds(p, k, f == Fix::z ? GLP_FX : GLP_LO, 0.0, 0.0);
  }
  if (!simplex(p, n, max_pivots))
    return {Status::failed, {}, {}};
  const int status = glp_get_status(p);
  if (status == GLP_NOFEAS)
    return {Status::empty, {}, phase_one_duals(p)};
  if (status != GLP_OPT && status != GLP_FEAS)
    return {Status::failed, {}, {}};
  Eigen::VectorXd z(n);
  for (Index j = 0; j < n; ++j)
    z(j) = std::max(0.0, glp_get_col_prim(p, static_cast<int>(j + 1)));
  return {Status::feasible, z * (q_max_ / m_max_), {}};
}

long LcpPolyhedron::pivots() const {
  return glp_get_it_cnt(lp_->prob.p);
}

std::optional<Eigen::VectorXd> LcpPolyhedron::farkas(const std::vector<Fix>& fix) const {
  const Index n = problem_.size();
  const QuietGlpk quiet;
  // Columns: y_i >= 0 and y_i^- >= 0 (held at zero except on the rows held at w_i = 0, where
  // y_i is y_i - y_i^-); rows: (M^T y)_j <= 0 (free where z_j is held at zero), and q . y = -1;
  // the least sum of |y|. Built once: only bounds change from node to node, and each solve
  // starts from the last basis, as vertex() does.
  glp_prob* p = lp_->farkas.p;
  const bool first = glp_get_num_cols(p) == 0;
  if (first) {
    Eigen::MatrixXd a(n + 1, 2 * n);
    a.topLeftCorner(n, n) = lp_->m.transpose();
    a.block(n, 0, 1, n) = lp_->q.transpose();
    a.rightCols(n) = -a.leftCols(n);
    glp_set_obj_dir(p, GLP_MIN);
    glp_add_rows(p, static_cast<int>(n + 1));
    glp_add_cols(p, static_cast<int>(2 * n));
    load_dense(p, a);
    glp_set_row_bnds(p, static_cast<int>(n + 1), GLP_FX, -1.0, -1.0);
    for (Index j = 0; j < 2 * n; ++j)
      glp_set_obj_coef(p, static_cast<int>(j + 1), 1.0);
  }
  for (Index j = 0; j < n; ++j) {
    const Fix f = fix[static_cast<std::size_t>(j)];
    const int k = static_cast<int>(j + 1);
    glp_set_row_bnds(p, k, f == Fix::z ? GLP_FR : GLP_UP, 0.0, 0.0);
    glp_set_col_bnds(p, k, GLP_LO, 0.0, 0.0);
    glp_set_col_bnds(p, static_cast<int>(n) + k, f == Fix::w ? GLP_LO : GLP_FX, 0.0, 0.0);
  }
  if (first)
    glp_adv_basis(p, 0);
  if (!simplex(p, n, std::numeric_limits<long>::max()) || glp_get_status(p) != GLP_OPT)
    return std::nullopt;
  Eigen::VectorXd y(n);
  for (Index j = 0; j < n; ++j)
    y(j) = std::max(0.0, glp_get_col_prim(p, static_cast<int>(j + 1))) -
           std::max(0.0, glp_get_col_prim(p, static_cast<int>(n + j + 1)));
  return y;
}

std::optional<Eigen::VectorXd> LcpPolyhedron::certificate() const {
  const Index n = problem_.size();
  if (n == 0)
    return std::nullopt;
  std::optional<Eigen::VectorXd> r = farkas(std::vector<Fix>(static_cast<std::size_t>(n)));
  const double top = r ? r->maxCoeff() : 0.0;
  if (!(top > 0.0))
    return std::nullopt;
  return Eigen::VectorXd(*r / top);
}

bool LcpPolyhedron::certifies(const std::vector<Fix>& fix, const Eigen::VectorXd& y) const {
  const Index n = problem_.size();
  if (static_cast<Index>(fix.size()) != n || n == 0 || y.size() != n)
    return false;
  std::vector<char> held_w(fix.size(), 0);
  std::vector<char> held_z(fix.size(), 0);
  for (std::size_t i = 0; i < fix.size(); ++i) {
    held_w[i] = fix[i] == Fix::w;
    held_z[i] = fix[i] == Fix::z;
  }
  // In double precision on the scaled data (max|M| = 1).
  return certifies_empty(lp_->q, y, lp_->m.transpose() * y,
                         lp_->m.cwiseAbs().transpose() * y.cwiseAbs(), 1.0, held_w, held_z,
                         kHeldSlack);
}

bool LcpPolyhedron::certified_by_duals(const std::vector<Fix>& fix,
                                       const Eigen::VectorXd& duals) const {
  // GLPK's sign convention of a row's dual depends on its bound: either sign may be the proof.
  return certifies(fix, duals) || certifies(fix, -duals);
}

bool LcpPolyhedron::certified_empty(const std::vector<Fix>& fix) {
  // Siblings and cousins are often empty for the same reason: a recent certificate is checked
  // (n^2) before an LP is solved (many pivots of n^2 each).
  for (auto c = certificates_.rbegin(); c != certificates_.rend(); ++c)
    if (certifies(fix, *c))
      return true;
  std::optional<Eigen::VectorXd> y = farkas(fix);
  if (!y || !certifies(fix, *y))
    return false;
  if (certificates_.size() == kKeptCertificates)
    certificates_.erase(certificates_.begin());
  certificates_.push_back(std::move(*y));
  return true;
}

}  // namespace bimrock
