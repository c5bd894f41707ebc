#pragma once
/// @file summary.json: what a run was (model size, settings, stages) and what it found (mean
/// strain, monitors, collapse bracket and mechanism, timings), for people and scripts alike.
#include <filesystem>
#include <vector>

#include <nlohmann/json.hpp>

#include <bimrock/analysis/elastic_analysis.hpp>
#include <bimrock/analysis/plastic_analysis.hpp>

namespace bimrock {

/// @param fields the final state (the elastic solution, or the last carried increment)
/// @param plastic the nonlinear result, or nullptr for an elastic run
/// @param files the result files written besides summary.json, relative to the folder
[[nodiscard]] nlohmann::json run_summary(const Model& model, const ElasticSolution& fields,
                                         const PlasticResult* plastic,
                                         const std::vector<std::string>& files);

void write_json(const nlohmann::json& json, const std::filesystem::path& file);

}  // namespace bimrock
