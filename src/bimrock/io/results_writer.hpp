#pragma once
/// @file The results folder of a run (docs/results.md), written all or nothing: summary.json,
/// blocks.csv, interfaces.csv, vtk/step_NNNN.vtu + results.pvd, and for a nonlinear run
/// history.csv, the load-displacement plots and pictures of the final state and the mechanism,
/// and on collapse mechanism.csv (with the mechanism's velocities in the last VTU step).
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <bimrock/analysis/elastic_analysis.hpp>
#include <bimrock/analysis/plastic_analysis.hpp>
#include <bimrock/io/case_reader.hpp>
#include <bimrock/io/output_folder.hpp>
#include <bimrock/io/vtk_writer.hpp>

namespace bimrock {

/// Pictures are drawn for models up to this many blocks (beyond, a picture is a grey blur and
/// slow to draw; ParaView is the tool then).
inline constexpr int kMaxPictureBlocks = 20000;

/// The size of the results of `model` [bytes], estimated before solving: one VTK file per
/// increment (the bulk), the rest small. Bisection of a step that fails adds a few steps.
[[nodiscard]] double estimate_output_bytes(const Model& model, const OutputOptions& options);

/// Throws InputError when estimate_output_bytes() exceeds the case's limits.output_mb.
void check_output_size(const Model& model, const Case& c);

/// The size of one VTK step of `model` (a .vtu of its blocks and interfaces) [bytes].
[[nodiscard]] double estimate_vtu_step_bytes(const Model& model);

/// Writes the results of an elastic run into `out` (replacing earlier results there).
void write_elastic_results(const Model& model, const ElasticSolution& solution,
                           const OutputOptions& options, const std::filesystem::path& out);

/// Writes the results of a nonlinear run as it goes: a VTK step every OutputOptions::vtk_every
/// carried increments, and the last one (pass on_increment() to run_plastic_analysis), the rest
/// in finish(). A step's time in results.pvd is its carried increment's number (0: the start).
/// Nothing appears in `out` before finish() returns; if the writer is destroyed unfinished, nothing
/// appears at all.
class PlasticResultsWriter {
 public:
  PlasticResultsWriter(const Model& model, OutputOptions options, const std::filesystem::path& out);

  void on_increment(const IncrementRecord& record, const AnalysisState& state);

  /// Writes the remaining files, moves the folder into place and returns the final fields.
  ElasticSolution finish(const PlasticResult& result);

 private:
  /// The fields of `state`, reached in stage `stage` (-1: the start, no bolt standing).
  [[nodiscard]] ElasticSolution fields_of(const AnalysisState& state, int stage) const;

  const Model& model_;
  OutputOptions options_;
  StagingFolder folder_;
  YieldPointIndex index_;
  std::vector<PvdEntry> steps_;
  int carried_ = 0;  // increments carried so far
  /// The last carried state, while it has no step of its own (vtk_every > 1).
  std::optional<AnalysisState> unwritten_;
  int unwritten_stage_ = -1;
};

}  // namespace bimrock
