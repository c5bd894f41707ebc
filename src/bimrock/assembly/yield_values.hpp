#pragma once
/// @file The values of the yield functions of every point at once (eqs. 20-23 with no
/// increment): what the per-increment choice of candidates and the per-round check of every
/// point read. The same laws as yield_modes.hpp (a test holds them equal), without gradients,
/// flow directions or allocations per point: a check reads every point of the model, the LCP
/// only a few of them.
#include <cstddef>
#include <vector>

#include <Eigen/Core>

#include <bimrock/assembly/plastic_state.hpp>
#include <bimrock/assembly/yield_points.hpp>
#include <bimrock/model/model.hpp>

namespace bimrock {

/// f of every mode of every point, flat: point p's modes are f(first[p]) ... f(first[p+1] - 1),
/// in the order of linearize().
struct YieldValues {
  std::vector<Eigen::Index> first;
  Eigen::VectorXd f;

  [[nodiscard]] Eigen::Index modes(std::size_t p) const { return first[p + 1] - first[p]; }
  [[nodiscard]] auto of(std::size_t p) const { return f.segment(first[p], modes(p)); }
  [[nodiscard]] double largest(std::size_t p) const { return of(p).maxCoeff(); }
};

/// The value of every yield function of a point that is absent (its block or one of its
/// interface's blocks excavated, a bolt not installed): far below any tolerance, so it is never
/// violated nor a candidate.
inline constexpr double kAbsentPoint = -1e300;

/// Evaluates the yield functions of a fixed set of points (what depends only on the materials,
/// such as the planes of a block's criterion, is worked out once).
class YieldEvaluator {
 public:
  /// @param present if given, what stands: the points of what does not get kAbsentPoint
  YieldEvaluator(const Model& model, const std::vector<YieldPoint>& points,
                 const Presence* present = nullptr);

  /// f at the unknowns u, with each point's plastic state. `scale`, if given, is raised to the
  /// largest stress component and the largest strength (c, sigma_t, or a block's c cos(phi))
  /// met, and a bolt spring's forces and capacities [N]: the scale of the yield tolerance.
  void evaluate(const std::vector<PlasticState>& states, const Eigen::VectorXd& u, YieldValues& out,
                double* scale = nullptr) const;

 private:
  struct BlockLaw {
    Eigen::Matrix3d d;      // D_b
    Eigen::MatrixX3d a;     // the planes' gradients, one row per mode
    double strength = 0.0;  // c cos(phi) cos(pi / n): f = a . sigma - strength
  };
  const Model& model_;
  const std::vector<YieldPoint>& points_;
  std::vector<Eigen::Index> first_;
  std::vector<BlockLaw> block_laws_;  // per block material (empty where it has no strength)
  std::vector<char> absent_;          // per point
};

}  // namespace bimrock
