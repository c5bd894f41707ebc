#pragma once
// One measured run of `bimrock bench`: a whole analysis of a generated model, each phase timed
// with its peak memory, and beside it the physical limit measured in the same run (CHOLMOD
// alone on the same K: analyze, factorize, one solve).
#include <filesystem>
#include <functional>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include <bimrock/analysis/elastic_analysis.hpp>
#include <bimrock/reference/reference_cases.hpp>
#include <bimrock/solve/stiffness_factor.hpp>

namespace bimrock::bench {

/// One run of one model: seconds and peak bytes per phase, in order, plus sizes.
struct Run {
  std::vector<std::pair<std::string, double>> seconds;
  std::map<std::string, double> peak_bytes;
  double limit_seconds = 0.0;  ///< analyze + factorize + one solve of the same K, alone
  double limit_peak_bytes = 0.0;
  double run_peak_bytes = 0.0;  ///< whole analysis, results not written
  int blocks = 0, interfaces = 0, unknowns = 0, yield_points = 0, lcp_rows_max = 0, increments = 0;
  bool collapsed = false;
  int condensations = 0;     ///< times K was condensed onto a plastic zone
  int reserve_switches = 0;  ///< times a zone was replaced by a reserve of the same factor
  int regions = 0;           ///< times K was factorized onto a region (zones then come from it)
  int zone_blocks = 0;       ///< blocks of the last zone
  /// The PETSc backend's solve (empty with CHOLMOD): its method, processes, iterations and
  /// residual, and the peak resident sets of all processes added up.
  std::string method;
  int processes = 1;
  int iterations = 0;
  double relative_residual = 0.0;
  double all_processes_peak_bytes = 0.0;
};

/// The elastic solve a run times: solve_elastic (CHOLMOD) or the PETSc backend's.
using ElasticSolve = std::function<ElasticSolution(const Model&, Run&)>;

/// How the runs are measured beside the analysis.
struct RunSettings {
  /// Measure the physical limit after the analysis (false: where CHOLMOD alone would not fit in
  /// memory beside the other processes; the row then has none).
  bool limit = true;
  /// The first process of an MPI run (the only one of a serial run): it writes the results and
  /// measures the limit; the others only take part in the solve.
  bool first_process = true;
  /// The plastic model's factorization of K (empty: CHOLMOD in this process), and what it is
  /// called in the table.
  std::function<StiffnessFactorization(const Model&)> stiffness;
  std::string stiffness_method;
  /// The processes of the run, and a value added up over them (empty: a serial run), for the
  /// peak memory of all of them.
  int processes = 1;
  std::function<double(double)> sum_over_processes;
};

/// The elastic model of `n` blocks (brick_mass_case) solved by `solve`, its results written
/// under `scratch`.
[[nodiscard]] Run run_elastic(int n, const std::filesystem::path& scratch,
                              const ElasticSolve& solve, const RunSettings& settings);

/// The plastic model of `n` blocks (abutment_case) pushed past its collapse in `increments`,
/// joints of `flow`; or, with `factor_of_safety`, pushed to 0.6 times its collapse thrust and
/// then its factor of safety found (the phase "(factor of safety)" of its timings).
[[nodiscard]] Run run_plastic(int n, int increments, JointFlow flow, bool factor_of_safety,
                              const std::filesystem::path& scratch, const RunSettings& settings);

}  // namespace bimrock::bench
