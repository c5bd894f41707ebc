#include <bimrock/solve/lcp.hpp>
#include <bimrock/solve/lcp_columns.hpp>

#include <algorithm>
#include <cmath>
#include <istream>
#include <limits>
#include <ostream>
#include <stdexcept>
#include <string>

namespace bimrock {

void check_lcp(const LcpProblem& problem) {
  if (problem.m.rows() != problem.m.cols() || problem.m.rows() != problem.q.size()) {
    throw std::invalid_argument("LCP: M must be square and match q in size");
  }
  if (!problem.m.allFinite() || !problem.q.allFinite()) {
    throw std::invalid_argument("LCP: M and q must be finite");
  }
}

const char* to_string(LcpStatus status) {
  switch (status) {
    case LcpStatus::solved:
      return "solved";
    case LcpStatus::no_solution:
      return "no solution";
    case LcpStatus::iteration_limit:
      return "iteration limit";
    case LcpStatus::numerical_failure:
      return "numerical failure";
    case LcpStatus::interrupted:
      return "interrupted";
  }
  return "?";
}

namespace {
// A kernel vector of a numerically singular active block is accurate to about a pivot
// tolerance; columns of M that are round-off residues of a cancellation (a mechanism) are held
// to a fraction of max|M| |r|_1 instead: far above their residues, far below a real stiffness.
constexpr double tol = 1e-8;
constexpr double floor_fraction = 1e-10;
}  // namespace

bool certifies_infeasibility(const Eigen::VectorXd& q, const Eigen::VectorXd& r,
                             const Eigen::VectorXd& mtr, const Eigen::VectorXd& mtr_size,
                             double m_max) {
  const std::vector<char> none(static_cast<std::size_t>(r.size()), 0);
  return certifies_empty(q, r, mtr, mtr_size, m_max, none, none, 0.0);
}

bool certifies_empty(const Eigen::VectorXd& q, const Eigen::VectorXd& r, const Eigen::VectorXd& mtr,
                     const Eigen::VectorXd& mtr_size, double m_max, const std::vector<char>& held_w,
                     const std::vector<char>& held_z, double held_slack) {
  const auto n = static_cast<std::size_t>(r.size());
  if (n == 0 || r.size() != q.size() || mtr.size() != r.size() || mtr_size.size() != r.size() ||
      held_w.size() != n || held_z.size() != n)
    return false;
  const double floor = floor_fraction * m_max * r.cwiseAbs().sum();
  const double sign_tol = tol * r.cwiseAbs().maxCoeff();
  double slack = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const auto k = static_cast<Eigen::Index>(i);
    if (held_w[i])
      slack += held_slack * std::abs(r(k));
    else if (r(k) < -sign_tol)
      return false;
    if (!held_z[i] && !(mtr(k) <= tol * mtr_size(k) + floor))
      return false;
  }
  return q.dot(r) + slack < -tol * q.cwiseAbs().dot(r.cwiseAbs());
}

double certified_from(const Eigen::VectorXd& q, const Eigen::VectorXd& dq,
                      const Eigen::VectorXd& r) {
  // q(t) . r = (q - dq) . r + t dq . r, held below -tol sum |q(t)| |r|, whose bound on [0, 1]
  // is sum (|q| + |dq|) |r|.
  const double at_zero = (q - dq).dot(r);
  const double slope = dq.dot(r);
  const double margin = tol * (q.cwiseAbs() + dq.cwiseAbs()).dot(r.cwiseAbs());
  if (!(slope < 0.0) || !(at_zero + slope < -margin))
    return 1.0;
  const double t = (-margin - at_zero) / slope;
  return t > 0.0 && t < 1.0 ? t : 1.0;
}

double LcpResiduals::worst_relative() const {
  return std::max({z_violation, w_violation, complementarity});
}

namespace {

// a / b for a scale b >= 0; 0 / 0 counts as 0 (an exactly zero row has an exactly zero w_i).
double ratio(double a, double b) {
  return a == 0.0 ? 0.0 : a / b;
}

}  // namespace

LcpResiduals measure(const Eigen::VectorXd& z, const Eigen::VectorXd& w, const Eigen::VectorXd& s) {
  const double z_scale = z.size() == 0 ? 0.0 : z.cwiseAbs().maxCoeff();
  LcpResiduals r;
  for (Eigen::Index i = 0; i < z.size(); ++i) {
    r.min_z = i == 0 ? z(i) : std::min(r.min_z, z(i));
    r.min_w = i == 0 ? w(i) : std::min(r.min_w, w(i));
    r.max_complementarity = std::max(r.max_complementarity, std::abs(z(i) * w(i)));
    r.z_violation = std::max(r.z_violation, ratio(std::max(0.0, -z(i)), z_scale));
    r.w_violation = std::max(r.w_violation, ratio(std::max(0.0, -w(i)), s(i)));
    const double pair = std::min(ratio(std::abs(z(i)), z_scale), ratio(std::abs(w(i)), s(i)));
    r.complementarity = std::max(r.complementarity, pair);
  }
  if (!z.allFinite() || !w.allFinite()) {
    // NaN compares false, so it drops out of the maxima above: a non-finite z or w fails every
    // check instead.
    const double fails = std::numeric_limits<double>::infinity();
    r.z_violation = fails;
    r.w_violation = fails;
    r.complementarity = fails;
  }
  return r;
}

bool same_up_to_scale(const LcpProblem& a, const LcpProblem& b) {
  if (a.size() != b.size() || a.m.rows() != b.m.rows() || a.m.cols() != b.m.cols() || a.m != b.m)
    return false;
  const double aa = a.q.squaredNorm();
  const double s = aa > 0.0 ? a.q.dot(b.q) / aa : 0.0;
  if (!(s > 0.0))
    return aa == 0.0 && b.q.squaredNorm() == 0.0;
  return (b.q - s * a.q).cwiseAbs().maxCoeff() <= 1e-12 * b.q.cwiseAbs().maxCoeff();
}

RelativePairs relative_pairs(const LcpProblem& problem, const Eigen::VectorXd& z) {
  const Eigen::VectorXd w = problem.m * z + problem.q;
  const Eigen::VectorXd s = problem.m.cwiseAbs() * z.cwiseAbs() + problem.q.cwiseAbs();
  const double z_max = z.cwiseAbs().maxCoeff();
  RelativePairs r{Eigen::VectorXd::Zero(problem.size()), Eigen::VectorXd::Zero(problem.size())};
  for (Eigen::Index i = 0; i < problem.size(); ++i) {
    r.z(i) = z_max > 0.0 ? z(i) / z_max : 0.0;
    r.w(i) = s(i) > 0.0 ? w(i) / s(i) : 0.0;
  }
  return r;
}

LcpResiduals measure(const LcpProblem& problem, const Eigen::VectorXd& z) {
  return measure(z, problem.m * z + problem.q,
                 problem.m.cwiseAbs() * z.cwiseAbs() + problem.q.cwiseAbs());
}

LcpResult make_lcp_result(const Eigen::VectorXd& q, const std::vector<Eigen::Index>& support,
                          const Eigen::MatrixXd& support_columns, LcpStatus status,
                          Eigen::VectorXd z, int steps) {
  Eigen::VectorXd zs(static_cast<Eigen::Index>(support.size()));
  for (std::size_t k = 0; k < support.size(); ++k)
    zs(static_cast<Eigen::Index>(k)) = z(support[k]);
  LcpResult result;
  result.status = status;
  result.w = support_columns * zs + q;
  result.residuals =
      measure(z, result.w, support_columns.cwiseAbs() * zs.cwiseAbs() + q.cwiseAbs());
  result.z = std::move(z);
  result.steps = steps;
  return result;
}

Eigen::VectorXd certified_ray(const Eigen::VectorXd& q, const std::vector<Eigen::Index>& support,
                              const Eigen::MatrixXd& support_columns,
                              const Eigen::VectorXd& r_support) {
  Eigen::VectorXd ray = Eigen::VectorXd::Zero(q.size());
  for (std::size_t k = 0; k < support.size(); ++k)
    ray(support[k]) = r_support(static_cast<Eigen::Index>(k));
  if (!certifies_infeasibility(q, ray, support_columns * r_support,
                               support_columns.cwiseAbs() * r_support.cwiseAbs(),
                               support_columns.cwiseAbs().maxCoeff()))
    return {};
  return ray / ray.maxCoeff();
}

LcpResult make_lcp_result(const LcpProblem& problem, LcpStatus status, Eigen::VectorXd z,
                          int steps) {
  LcpResult result;
  result.status = status;
  result.w = problem.m * z + problem.q;
  result.residuals = measure(problem, z);
  result.z = std::move(z);
  result.steps = steps;
  return result;
}

namespace {
constexpr const char* kHeader = "bimrock-lcp";
constexpr int kVersion = 1;
}  // namespace

void write_lcp(std::ostream& out, const LcpProblem& problem) {
  const auto old_precision = out.precision(std::numeric_limits<double>::max_digits10);
  out << kHeader << ' ' << kVersion << '\n' << problem.size() << '\n';
  for (Eigen::Index i = 0; i < problem.size(); ++i) {
    for (Eigen::Index j = 0; j < problem.size(); ++j)
      out << problem.m(i, j) << ' ';
    out << "  " << problem.q(i) << '\n';
  }
  out.precision(old_precision);
}

LcpProblem read_lcp(std::istream& in) {
  std::string header;
  int version = 0;
  Eigen::Index n = -1;
  if (!(in >> header >> version >> n) || header != kHeader || version != kVersion || n < 0) {
    throw std::runtime_error("read_lcp: not a bimrock-lcp version 1 stream");
  }
  LcpProblem p{Eigen::MatrixXd(n, n), Eigen::VectorXd(n)};
  for (Eigen::Index i = 0; i < n; ++i) {
    for (Eigen::Index j = 0; j < n; ++j)
      in >> p.m(i, j);
    in >> p.q(i);
  }
  if (!in)
    throw std::runtime_error("read_lcp: stream ended before the " + std::to_string(n) + " x " +
                             std::to_string(n) + " problem was read");
  return p;
}

}  // namespace bimrock
