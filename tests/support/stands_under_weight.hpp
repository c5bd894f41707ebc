#pragma once
// The checks of a structure that must stand under its own weight (one gravity stage): the
// analysis carries the whole stage, neither stopped nor collapsed, and after every increment the
// supports' reaction balances the weight carried so far (a conservation law).
#include <algorithm>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <bimrock/analysis/field_results.hpp>
#include <bimrock/analysis/plastic_analysis.hpp>

#include "support/support_reaction.hpp"

namespace bimrock::testing {

/// `weight` [N] is the structure's (over the model's thickness), `what` names the case in
/// failure messages.
inline void expect_stands_under_weight(const Model& model, double weight, const std::string& what) {
  YieldPointIndex index;
  const std::vector<YieldPoint> points = make_yield_points(model, &index);
  double worst_balance = 0.0;
  const PlasticResult r = run_plastic_analysis(
      model, PlasticOptions{}, [&](const IncrementRecord& rec, const AnalysisState& state) {
        const PlasticParts plastic{&index, &state.points};
        const Vec2 load(0.0, -rec.stage_factor * weight);
        const Vec2 reaction = support_reaction(model, state.u, plastic);
        worst_balance = std::max(worst_balance, (load + reaction).norm() / weight);
      });
  EXPECT_FALSE(r.stopped.has_value()) << what << ": " << r.stopped->reason;
  EXPECT_FALSE(r.collapse.has_value()) << what;
  EXPECT_NEAR(r.state.stage_factor, 1.0, 1e-12) << what;
  EXPECT_LE(worst_balance, 1e-8) << what;
}

}  // namespace bimrock::testing
