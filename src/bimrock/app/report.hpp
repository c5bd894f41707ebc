#pragma once
// Short human-readable tables printed during and at the end of a run.
#include <filesystem>

#include <bimrock/analysis/elastic_analysis.hpp>
#include <bimrock/analysis/plastic_analysis.hpp>

namespace bimrock {

void print_model(const Model& model);
/// `check`: the estimated peak memory of a run of the model (analysis/memory_estimate.hpp).
void print_memory_estimate(const Model& model);
void print_summary(const Model& model, const ElasticSolution& solution,
                   const std::filesystem::path& out);

/// One line per carried increment of a nonlinear analysis.
/// One progress line per carried increment: stage k of n, step and the steps asked for, the
/// state, the time since the analysis started and a rough estimate of the time left (in
/// proportion to the increments still to go; near a collapse they take longer).
void print_increment(const Model& model, const IncrementRecord& record, double elapsed);
void print_plastic_summary(const Model& model, const PlasticResult& result,
                           const ElasticSolution& fields, const std::filesystem::path& out);

}  // namespace bimrock
