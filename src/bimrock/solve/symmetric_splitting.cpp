#include <bimrock/solve/symmetric_splitting.hpp>

#include <algorithm>
#include <deque>
#include <limits>

#include <Eigen/QR>

namespace bimrock {

namespace {

/// The accelerated run's remainders: Anderson's method on y, combining the last iterates'
/// images g_k = E z_k and residuals f_k = g_k - y_k (up to depth + 1 of each).
class AcceleratedIterates {
 public:
  AcceleratedIterates(const SplittingRemainder& remainder, const Eigen::VectorXd& start, int depth)
      : remainder_(remainder), depth_(depth), y_(remainder(start)) {}

  [[nodiscard]] const Eigen::VectorXd& y() const { return y_; }

  /// After the inner solution z of y: y <- g - dG gamma, with g = E z and gamma the least squares
  /// solution of dF gamma = f (dF, dG the differences of consecutive residuals and images).
  void advance(const Eigen::VectorXd& z, Eigen::Index /*changed*/) {
    const Eigen::VectorXd g = remainder_(z);
    residuals_.push_back(g - y_);
    images_.push_back(g);
    if (residuals_.size() > static_cast<std::size_t>(depth_) + 1) {
      residuals_.pop_front();
      images_.pop_front();
    }
    const auto k = static_cast<Eigen::Index>(residuals_.size()) - 1;
    if (k == 0) {
      y_ = g;
      return;
    }
    Eigen::MatrixXd df(g.size(), k);
    Eigen::MatrixXd dg(g.size(), k);
    for (Eigen::Index j = 0; j < k; ++j) {
      const auto i = static_cast<std::size_t>(j);
      df.col(j) = residuals_[i + 1] - residuals_[i];
      dg.col(j) = images_[i + 1] - images_[i];
    }
    // Column pivoting drops differences that are (nearly) dependent on the others.
    const Eigen::VectorXd gamma = df.colPivHouseholderQr().solve(residuals_.back());
    y_ = g - dg * gamma;
  }

 private:
  const SplittingRemainder& remainder_;
  int depth_;
  Eigen::VectorXd y_;
  std::deque<Eigen::VectorXd> residuals_;
  std::deque<Eigen::VectorXd> images_;
};

/// The damped run's iterates z_k+1 = z_k + omega (z^ - z_k), y = E z: omega halves where
/// `stalled_after` iterates in a row change no fewer rows of the active set than the fewest so
/// far (rows swapping back and forth: the iteration matrix has an eigenvalue near -1).
class DampedIterates {
 public:
  DampedIterates(const SplittingRemainder& remainder, const Eigen::VectorXd& start,
                 const SplittingOptions& options)
      : remainder_(remainder), options_(options), z_(start), y_(remainder(start)) {}

  [[nodiscard]] const Eigen::VectorXd& y() const { return y_; }

  /// After the inner solution z, whose active set differs from the last one's in `changed`
  /// rows (the first inner solution is taken whole).
  void advance(const Eigen::VectorXd& z, Eigen::Index changed) {
    if (first_) {
      first_ = false;
    } else {
      stalled_ = changed >= least_ ? stalled_ + 1 : 0;
      least_ = std::min(least_, changed);
      if (stalled_ >= options_.stalled_after && relaxation_ > options_.least_relaxation) {
        relaxation_ /= 2.0;
        stalled_ = 0;
        least_ = changed;
      }
    }
    z_ += relaxation_ * (z - z_);
    y_ = remainder_(z_);
  }

 private:
  const SplittingRemainder& remainder_;
  const SplittingOptions& options_;
  Eigen::VectorXd z_;
  Eigen::VectorXd y_;
  bool first_ = true;
  double relaxation_ = 1.0;
  int stalled_ = 0;
  Eigen::Index least_ = std::numeric_limits<Eigen::Index>::max();
};

/// One run of the splitting, its remainders y_k given by `iterates`.
template <class Iterates>
SplittingResult run(const Eigen::VectorXd& q, const SymmetricLcpSolve& solve_symmetric,
                    const ActiveSetProposal& propose, const Eigen::VectorXd* warm,
                    int max_iterations, Iterates iterates) {
  SplittingResult out;
  const Eigen::Index n = q.size();
  Eigen::VectorXd active = warm ? *warm : Eigen::VectorXd::Zero(n);
  Eigen::VectorXd proposed;  // the last active set tried
  for (int k = 0; k < max_iterations; ++k) {
    const LcpResult inner =
        solve_symmetric(Eigen::VectorXd(q + iterates.y()), k == 0 && !warm ? nullptr : &active);
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
    iterates.advance(inner.z, changed);
  }
  return out;
}

}  // namespace

SplittingResult solve_by_splitting(const Eigen::VectorXd& q, const SplittingRemainder& remainder,
                                   const SymmetricLcpSolve& solve_symmetric,
                                   const ActiveSetProposal& propose, const Eigen::VectorXd& start,
                                   const Eigen::VectorXd* warm, const SplittingOptions& options) {
  SplittingResult accelerated = run(q, solve_symmetric, propose, warm, options.max_iterations,
                                    AcceleratedIterates(remainder, start, options.anderson_depth));
  // The first two iterates are plain in both runs: a failure before any combination would
  // come back the same.
  if (accelerated.solved || !options.damped_after || accelerated.iterations < 2)
    return accelerated;
  SplittingResult damped = run(q, solve_symmetric, propose, warm, options.max_iterations,
                               DampedIterates(remainder, start, options));
  damped.iterations += accelerated.iterations;
  damped.proposals += accelerated.proposals;
  if (damped.z.size() == 0)
    damped.z.swap(accelerated.z);
  return damped;
}

}  // namespace bimrock
