#pragma once
// Short human-readable tables printed at the end of a run.
#include <filesystem>

#include <bimrock/analysis/elastic_analysis.hpp>

namespace bimrock {

void print_model(const Model& model);
void print_summary(const Model& model, const ElasticSolution& solution,
                   const std::filesystem::path& out);

}  // namespace bimrock
