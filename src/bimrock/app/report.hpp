#pragma once
// Short human-readable tables printed during and at the end of a run.
#include <filesystem>

#include <bimrock/analysis/elastic_analysis.hpp>
#include <bimrock/analysis/plastic_analysis.hpp>

namespace bimrock {

void print_model(const Model& model);
void print_summary(const Model& model, const ElasticSolution& solution,
                   const std::filesystem::path& out);

/// One line per carried increment of a nonlinear analysis.
void print_increment(const Model& model, const IncrementRecord& record);
void print_plastic_summary(const Model& model, const PlasticResult& result,
                           const ElasticSolution& fields, const std::filesystem::path& out);

}  // namespace bimrock
