#include <bimrock/solve/symmetric_splitting.hpp>

#include <algorithm>
#include <deque>
#include <limits>
#include <optional>
#include <vector>

#include <Eigen/QR>

namespace bimrock {

namespace {

/// The accelerated run's remainders: Anderson's method on y, combining the last iterates'
/// images g_k = E z_k and residuals f_k = g_k - y_k (up to depth + 1 of each).
class AcceleratedIterates {
 public:
  AcceleratedIterates(const SplittingRemainder& remainder, const Eigen::VectorXd& start, int depth)
      : depth_(depth), y_(remainder(start)) {}

  /// Newton steps are taken between these iterates (see run).
  static constexpr bool kNewtonSteps = true;

  [[nodiscard]] const Eigen::VectorXd& y() const { return y_; }
  /// The next inner LCP is solved at y instead (a Newton step, or its taking back): the pair
  /// (y, E z) it gives is as good a difference for the combinations as any other.
  void jump(const Eigen::VectorXd& y) { y_ = y; }

  /// After the inner solution z of y, g = E z: y <- g - dG gamma, with gamma the least squares
  /// solution of dF gamma = f (dF, dG the differences of consecutive residuals and images).
  void advance(const Eigen::VectorXd& /*z*/, const Eigen::VectorXd& g, Eigen::Index /*changed*/) {
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

  /// No Newton steps: this run follows where the accelerated one failed, and keeps near the
  /// plain iterates.
  static constexpr bool kNewtonSteps = false;

  [[nodiscard]] const Eigen::VectorXd& y() const { return y_; }

  /// After the inner solution z, whose active set differs from the last one's in `changed`
  /// rows (the first inner solution is taken whole).
  void advance(const Eigen::VectorXd& z, const Eigen::VectorXd& /*g*/, Eigen::Index changed) {
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

/// What one run of the splitting works with.
struct SplittingProblem {
  const Eigen::VectorXd& q;
  const SplittingRemainder& remainder;
  const SymmetricLcpSolve& solve_symmetric;
  const ActiveSetProposal& propose;
  const Eigen::VectorXd* warm;
  const SplittingOptions& options;
};

/// A Newton step whose inner LCP is not solved yet: where it turns out unsolved, or its residual
/// not low enough, the iteration goes back to the remainder and active set it left.
struct PendingNewtonStep {
  Eigen::VectorXd y;
  Eigen::VectorXd active;
  double residual = 0.0;
};

/// The inner solutions of the first two iterates, which are plain in both runs (y_0 = E start,
/// y_1 = E z_0): the damped run takes them from the accelerated one instead of solving them again.
using PlainIterates = std::vector<LcpResult>;
constexpr std::size_t kPlainIterates = 2;

/// One run of the splitting, its remainders y_k given by `iterates` (with Newton steps between
/// them where Iterates::kNewtonSteps and the options ask for them). The first inner solutions
/// are taken from `plain` where it holds them, else solved and added to it.
template <class Iterates>
SplittingResult run(const SplittingProblem& p, Iterates iterates, PlainIterates& plain) {
  constexpr bool kNewton = Iterates::kNewtonSteps;
  const SplittingOptions& options = p.options;
  const bool newton = kNewton && options.newton;
  SplittingResult out;
  const Eigen::Index n = p.q.size();
  Eigen::VectorXd active = p.warm ? *p.warm : Eigen::VectorXd::Zero(n);
  Eigen::VectorXd proposed;  // the last active set tried
  Eigen::VectorXd y = iterates.y();
  std::optional<PendingNewtonStep> pending;
  int pause = 0;  // iterates left before the next Newton step
  for (int k = 0; k < options.max_iterations; ++k) {
    const auto i = static_cast<std::size_t>(k);
    const bool known = i < plain.size();
    const LcpResult inner =
        known ? plain[i]
              : p.solve_symmetric(Eigen::VectorXd(p.q + y), k == 0 && !p.warm ? nullptr : &active,
                                  pending.has_value());
    if (!known && i < kPlainIterates)
      plain.push_back(inner);
    const bool inner_solved = inner.status == LcpStatus::solved && inner.z.size() == n;
    Eigen::VectorXd g;  // E z, for the accelerated iterates (the damped ones form their own)
    if (kNewton && inner_solved)
      g = p.remainder(inner.z);
    if constexpr (kNewton) {
      if (pending &&
          (!inner_solved || !((g - y).norm() < options.newton_decrease * pending->residual))) {
        // The step asked more of the frozen strengths than they have, or did not bring the
        // iterates nearer the fixed point: back to where it left.
        y = std::move(pending->y);
        active = std::move(pending->active);
        iterates.jump(y);
        pending.reset();
        pause = options.newton_pause;
        continue;
      }
      pending.reset();
    }
    if (!inner_solved)
      return out;
    out.z = inner.z;
    ++out.iterations;
    const Eigen::VectorXd now = (inner.z.array() > 0.0).cast<double>();
    const auto changed = static_cast<Eigen::Index>((now - active).cwiseAbs().sum());
    active = now;
    // The active set {i : z_i > 0} held from the last iterate, or nearly (before a Newton
    // step): a proposal (each set once).
    const bool near = newton && pause == 0 && changed <= options.newton_changed_rows;
    ProposalOutcome tried;
    if (k > 0 && (changed == 0 || near) && (proposed.size() != n || active != proposed)) {
      proposed = active;
      ++out.proposals;
      tried = p.propose(active);
      if (tried.solved) {
        out.solved = true;
        return out;
      }
    }
    const double residual = kNewton ? (g - y).norm() : 0.0;
    iterates.advance(inner.z, g, changed);
    y = iterates.y();
    pause = std::max(0, pause - 1);
    if constexpr (kNewton) {
      if (newton && tried.z.size() == n && tried.z.allFinite()) {
        // The Newton step: the remainder of the proposal's multipliers (those it took below
        // zero count as zero, as the inner LCP would hold them).
        pending = PendingNewtonStep{y, active, residual};
        y = p.remainder(Eigen::VectorXd(tried.z.cwiseMax(0.0)));
        iterates.jump(y);
        active = (tried.z.array() > 0.0).cast<double>();
      }
    }
  }
  return out;
}

}  // namespace

SplittingResult solve_by_splitting(const Eigen::VectorXd& q, const SplittingRemainder& remainder,
                                   const SymmetricLcpSolve& solve_symmetric,
                                   const ActiveSetProposal& propose, const Eigen::VectorXd& start,
                                   const Eigen::VectorXd* warm, const SplittingOptions& options) {
  const SplittingProblem problem{q, remainder, solve_symmetric, propose, warm, options};
  PlainIterates plain;
  SplittingResult accelerated =
      run(problem, AcceleratedIterates(remainder, start, options.anderson_depth), plain);
  // The first two iterates are plain in both runs: a failure before any combination would
  // come back the same.
  if (accelerated.solved || !options.damped_after || accelerated.iterations < 2)
    return accelerated;
  SplittingResult damped = run(problem, DampedIterates(remainder, start, options), plain);
  damped.iterations += accelerated.iterations;
  damped.proposals += accelerated.proposals;
  if (damped.z.size() == 0)
    damped.z.swap(accelerated.z);
  return damped;
}

}  // namespace bimrock
