#include "model_lcps.hpp"

#include <algorithm>
#include <cstdio>
#include <optional>
#include <stdexcept>
#include <vector>

#include <bimrock/analysis/plastic_analysis.hpp>
#include <bimrock/assembly/global_system.hpp>
#include <bimrock/assembly/yield_modes.hpp>
#include <bimrock/assembly/yield_points.hpp>
#include <bimrock/assembly/yield_system.hpp>
#include <bimrock/assembly/yield_values.hpp>
#include <bimrock/reference/reference_cases.hpp>
#include <bimrock/solve/sparse_cholesky.hpp>

#include "brick_mass.hpp"

namespace bimrock::bench {
namespace {

// The factor of K and the yield points of a model: what every increment of it shares.
struct ModelContext {
  const Model& model;
  std::vector<YieldPoint> points;
  SparseCholesky k;

  explicit ModelContext(const Model& m) : model(m), points(make_yield_points(m)) {
    const SparseMatrix lower = assemble_stiffness_lower(m);
    k.analyze(lower, 6);
    if (!k.factorize(lower))
      throw std::runtime_error("model_lcps: K is not positive definite");
  }
};

// The yield points of the LCP of an increment from `before` by the elastic displacement `du`:
// as plastic_analysis.cpp's select_candidate_rows, the open points and those whose elastic
// predictor exceeds yield by more than the tolerance of the analysis' final check (same stress
// scale); plus, when known, the points whose plastic state the analysis changed in that
// increment (`after`), which its later rounds added.
std::vector<int> candidate_points(const ModelContext& ctx, const AnalysisState& before,
                                  const Eigen::VectorXd& du, const AnalysisState* after) {
  const double yield_tolerance = PlasticOptions{}.yield_tolerance;
  const std::size_t n = ctx.points.size();
  const YieldEvaluator evaluator(ctx.model, ctx.points);
  YieldValues now;
  YieldValues predicted_f;  // f + df: f is linear in the stress at a fixed plastic state
  double scale = 0.0;
  evaluator.evaluate(before.points, before.u, now, &scale);
  evaluator.evaluate(before.points, Eigen::VectorXd(before.u + du), predicted_f, &scale);
  const double tol = yield_tolerance * std::max(scale, 1.0);
  std::vector<int> candidates;
  for (std::size_t p = 0; p < n; ++p) {
    const PlasticState& b = before.points[p];
    bool changed = false;
    if (after) {
      const PlasticState& a = after->points[p];
      changed = a.plastic != b.plastic || a.slip != b.slip || a.gap != b.gap;
    }
    if (b.gap > 0.0 || predicted_f.largest(p) > tol || changed)
      candidates.push_back(static_cast<int>(p));
  }
  return candidates;
}

bool is_symmetric(const Eigen::MatrixXd& m) {
  return (m - m.transpose()).cwiseAbs().maxCoeff() <= 1e-10 * m.cwiseAbs().maxCoeff();
}

// The LCP of a load-controlled increment `step` of the stage whose reference displacement is
// x_ref, from state `before`, on the given yield points (plastic_analysis.cpp's solve_lcp), and
// the analysis' warm start.
void increment_lcp(const ModelContext& ctx, const AnalysisState& before,
                   const Eigen::VectorXd& x_ref, double step, const std::vector<int>& candidates,
                   ModelLcp& lcp) {
  const YieldSystem sys =
      assemble_yield_system(ctx.model, ctx.points, before.points, before.u, candidates);
  const int m = sys.size();
  const Eigen::MatrixXd y = ctx.k.solve(Eigen::MatrixXd(sys.phi));  // K^-1 Phi
  LcpProblem& problem = lcp.problem;
  problem.m = Eigen::MatrixXd(sys.n) - sys.c * y;
  Eigen::VectorXd gap_old = Eigen::VectorXd::Zero(m);
  for (int r = 0; r < m; ++r) {
    const YieldRow& row = sys.rows[r];
    if (ctx.points[row.point].is_interface() && row.mode == kOpeningMode)
      gap_old(r) = before.points[row.point].gap;
  }
  problem.q = -sys.f0 - (sys.c * x_ref) * step - problem.m * gap_old;
  lcp.warm_start = gap_old.size() > 0 && gap_old.maxCoeff() > 0.0 ? gap_old : Eigen::VectorXd();
  lcp.symmetric = is_symmetric(problem.m);
}

}  // namespace

ModelLcp brick_mass_gravity_lcp(int n_blocks) {
  // The first of 5 equal gravity increments is the one increment of gravity / 5: the same
  // step x x_ref. Running the analysis over it gives the points its rounds added.
  CaseSpec spec = plastic_brick_mass_case(n_blocks, 0.0, 1);
  spec.stages[0].loads.gravity *= 0.2;
  const Model model = build_model(spec);
  const PlasticResult run = run_plastic_analysis(model);
  if (run.history.size() != 1)
    throw std::runtime_error("model_lcps: the brick mass did not carry its first increment");
  ModelContext ctx(model);
  AnalysisState before;
  before.u = Eigen::VectorXd::Zero(model.n_dofs());
  before.points.assign(ctx.points.size(), PlasticState{});
  const Eigen::VectorXd x_ref = ctx.k.solve(assemble_loads(model, model.stages[0].loads));
  ModelLcp lcp;
  lcp.model = "brick mass";
  lcp.source = "brick mass: " + std::to_string(model.n_blocks()) +
               " blocks, no-tension joints, gravity increment 1 of 5";
  lcp.blocks = model.n_blocks();
  increment_lcp(ctx, before, x_ref, 1.0, candidate_points(ctx, before, x_ref, &run.state), lcp);
  lcp.analysis_rows = run.history.front().lcp_size;
  lcp.analysis_active_set_iterations = run.history.front().active_set_iterations;
  lcp.analysis_pivots = run.history.front().pivots;
  return lcp;
}

namespace {

// The wall pushed to `factor` times the sliding load of its top row in 10 steps: the LCP of the
// last increment the analysis carries.
ModelLcp wall_lcp(int n_blocks, double factor, const std::string& name) {
  const Model model = build_model(wall_case(n_blocks, 10, factor * wall_collapse_shear()));
  // The states before and after the latest carried increment.
  struct Carried {
    IncrementRecord record;
    AnalysisState state;
  };
  std::optional<Carried> previous, last;
  // The collapse is bracketed coarsely (to 10 %): only the state before it matters here, and
  // every bisection past it costs a Lemke solve of the whole LCP.
  PlasticOptions options;
  options.bracket_tolerance = 0.1;
  const PlasticResult run =
      run_plastic_analysis(model, options, [&](const IncrementRecord& r, const AnalysisState& s) {
        previous = std::move(last);
        last = Carried{r, s};
      });
  if (!run.collapse || !previous || last->record.stage != 1)
    throw std::runtime_error("model_lcps: the wall did not collapse in its push stage");
  ModelContext ctx(model);
  const Carried& before = *previous;
  const double start = before.record.stage == 1 ? before.record.stage_factor : 0.0;
  const double step = last->record.stage_factor - start;
  const Eigen::VectorXd x_ref = ctx.k.solve(assemble_loads(model, model.stages[1].loads));
  char source[200];
  std::snprintf(source, sizeof source,
                "%s: wall of %d blocks, the increment from %.4g to %.4g times the top row's "
                "sliding load (the collapse is bracketed in [%.4g, %.4g])",
                name.c_str(), model.n_blocks(), factor * start, factor * last->record.stage_factor,
                factor * run.collapse->carried, factor * run.collapse->failed);
  ModelLcp lcp;
  lcp.model = name;
  lcp.source = source;
  lcp.blocks = model.n_blocks();
  increment_lcp(ctx, before.state, x_ref, step,
                candidate_points(ctx, before.state, step * x_ref, &last->state), lcp);
  lcp.analysis_rows = last->record.lcp_size;
  lcp.analysis_active_set_iterations = last->record.active_set_iterations;
  lcp.analysis_pivots = last->record.pivots;
  return lcp;
}

}  // namespace

ModelLcp wall_near_collapse_lcp(int n_blocks) {
  return wall_lcp(n_blocks, 1.3, "wall near collapse");
}

ModelLcp wall_at_limit_lcp(int n_blocks) {
  return wall_lcp(n_blocks, 1.25, "wall at its limit");
}

}  // namespace bimrock::bench
