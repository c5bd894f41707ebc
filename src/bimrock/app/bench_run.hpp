#pragma once
// One measured run of `bimrock bench`: a whole analysis of a generated model, each phase timed
// with its peak memory, and beside it the physical limit measured in the same run (CHOLMOD
// alone on the same K: analyze, factorize, one solve).
#include <filesystem>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include <bimrock/reference/reference_cases.hpp>

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
};

/// The elastic model of `n` blocks (brick_mass_case), its results written under `scratch`.
[[nodiscard]] Run run_elastic(int n, const std::filesystem::path& scratch);

/// The plastic model of `n` blocks (abutment_case) pushed past its collapse in `increments`,
/// joints of `flow`; or, with `factor_of_safety`, pushed to 0.6 times its collapse thrust and
/// then its factor of safety found (the phase "(factor of safety)" of its timings).
[[nodiscard]] Run run_plastic(int n, int increments, JointFlow flow, bool factor_of_safety,
                              const std::filesystem::path& scratch);

}  // namespace bimrock::bench
