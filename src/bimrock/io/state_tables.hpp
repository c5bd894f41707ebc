#pragma once
/// @file The state of every block and interface as CSV tables (SI units, stated in the headers).
#include <filesystem>

#include <bimrock/analysis/elastic_analysis.hpp>

namespace bimrock {

/// blocks.csv: per block its centroid, unknowns d (eq. 1), strain, stress and plastic strain.
void write_blocks_csv(const Model& model, const ElasticSolution& fields,
                      const std::filesystem::path& file);

/// interfaces.csv: per interface its blocks (j = -1: a support), ends, and at each of its two
/// integration points the position, relative displacement, stress and plastic part.
void write_interfaces_csv(const Model& model, const ElasticSolution& fields,
                          const std::filesystem::path& file);

/// bolts.csv: per bolt spring its bolt, blocks and points, whether it stands, its forces (per
/// bolt), displacement since installation, plastic part, and its use of the capacity.
void write_bolts_csv(const Model& model, const ElasticSolution& fields,
                     const std::filesystem::path& file);

}  // namespace bimrock
