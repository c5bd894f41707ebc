#include <bimrock/solve/symmetric_splitting.hpp>

#include <algorithm>
#include <deque>
#include <limits>

#include <Eigen/QR>

namespace bimrock {

namespace {

/// The last iterates' remainders y_k, their images g_k = E z_k and residuals f_k = g_k - y_k,
/// up to depth + 1 of each.
class AndersonMixing {
 public:
  explicit AndersonMixing(int depth) : depth_(depth) {}

  /// The next remainder after the image g of y: g - dG gamma, with gamma the least squares
  /// solution of dF gamma = f (dF, dG the differences of consecutive residuals and images).
  [[nodiscard]] Eigen::VectorXd next(const Eigen::VectorXd& y, const Eigen::VectorXd& g) {
    residuals_.push_back(g - y);
    images_.push_back(g);
    if (residuals_.size() > static_cast<std::size_t>(depth_) + 1) {
      residuals_.pop_front();
      images_.pop_front();
    }
    const auto k = static_cast<Eigen::Index>(residuals_.size()) - 1;
    if (k == 0)
      return g;
    Eigen::MatrixXd df(g.size(), k);
    Eigen::MatrixXd dg(g.size(), k);
    for (Eigen::Index j = 0; j < k; ++j) {
      const auto i = static_cast<std::size_t>(j);
      df.col(j) = residuals_[i + 1] - residuals_[i];
      dg.col(j) = images_[i + 1] - images_[i];
    }
    // Column pivoting drops differences that are (nearly) dependent on the others.
    const Eigen::VectorXd gamma = df.colPivHouseholderQr().solve(residuals_.back());
    return g - dg * gamma;
  }

 private:
  int depth_;
  std::deque<Eigen::VectorXd> residuals_;
  std::deque<Eigen::VectorXd> images_;
};

/// The relaxation of the damped run: it halves where `stalled_after` iterates in a row change no
/// fewer rows of the active set than the fewest so far (rows swapping back and forth: the
/// iteration matrix has an eigenvalue near -1).
class Damping {
 public:
  explicit Damping(const SplittingOptions& options) : options_(options) {}

  [[nodiscard]] double after(Eigen::Index changed) {
    stalled_ = changed >= least_ ? stalled_ + 1 : 0;
    least_ = std::min(least_, changed);
    if (stalled_ >= options_.stalled_after && relaxation_ > options_.least_relaxation) {
      relaxation_ /= 2.0;
      stalled_ = 0;
      least_ = changed;
    }
    return relaxation_;
  }

 private:
  const SplittingOptions& options_;
  double relaxation_ = 1.0;
  int stalled_ = 0;
  Eigen::Index least_ = std::numeric_limits<Eigen::Index>::max();
};

/// One run of the splitting from z_0 = start: accelerated by `mixing`, or damped by `damping`.
SplittingResult run(const Eigen::VectorXd& q, const SplittingRemainder& remainder,
                    const SymmetricLcpSolve& solve_symmetric, const ActiveSetProposal& propose,
                    const Eigen::VectorXd& start, const Eigen::VectorXd* warm, int max_iterations,
                    AndersonMixing* mixing, Damping* damping) {
  SplittingResult out;
  const Eigen::Index n = q.size();
  Eigen::VectorXd active = warm ? *warm : Eigen::VectorXd::Zero(n);
  Eigen::VectorXd proposed;  // the last active set tried
  Eigen::VectorXd z = start;
  Eigen::VectorXd y = remainder(start);
  for (int k = 0; k < max_iterations; ++k) {
    const LcpResult inner =
        solve_symmetric(Eigen::VectorXd(q + y), k == 0 && !warm ? nullptr : &active);
    if (inner.status != LcpStatus::solved || inner.z.size() != n)
      return out;
    out.z = inner.z;
    ++out.iterations;
    const Eigen::VectorXd now = (inner.z.array() > 0.0).cast<double>();
    const auto changed = static_cast<Eigen::Index>((now - active).cwiseAbs().sum());
    active = now;
    // The active set {i : z_i > 0} held from the last iterate: a proposal (each set once).
    if (k > 0 && changed == 0 && (proposed.size() != n || active != proposed)) {
      proposed = active;
      ++out.proposals;
      if (propose(active)) {
        out.solved = true;
        return out;
      }
    }
    if (mixing) {
      y = mixing->next(y, remainder(inner.z));
    } else {
      z += (k > 0 ? damping->after(changed) : 1.0) * (inner.z - z);
      y = remainder(z);
    }
  }
  return out;
}

}  // namespace

SplittingResult solve_by_splitting(const Eigen::VectorXd& q, const SplittingRemainder& remainder,
                                   const SymmetricLcpSolve& solve_symmetric,
                                   const ActiveSetProposal& propose, const Eigen::VectorXd& start,
                                   const Eigen::VectorXd* warm, const SplittingOptions& options) {
  AndersonMixing mixing(options.anderson_depth);
  SplittingResult accelerated = run(q, remainder, solve_symmetric, propose, start, warm,
                                    options.max_iterations, &mixing, nullptr);
  // The first two iterates are plain in both runs: a failure before any combination would
  // come back the same.
  if (accelerated.solved || !options.damped_after || accelerated.iterations < 2)
    return accelerated;
  Damping damping(options);
  SplittingResult damped = run(q, remainder, solve_symmetric, propose, start, warm,
                               options.max_iterations, nullptr, &damping);
  damped.iterations += accelerated.iterations;
  damped.proposals += accelerated.proposals;
  if (damped.z.size() == 0)
    damped.z.swap(accelerated.z);
  return damped;
}

}  // namespace bimrock
