#pragma once
/// @file What each trial increment of a plastic analysis ended with, recorded by one run and
/// replayed by another run of the same model: the oracle of `bimrock bench --oracle`. Replayed,
/// each trial's LCP holds the points of the recorded one's last round and starts from its
/// final active rows, on one zone condensed at the start for every trial. The time of that run
/// is what the analysis would cost if its solvers guessed every increment right at once: a floor
/// for the strategy of candidates, rounds, zones and active-set iterations (docs/performance.md).
#include <cstddef>
#include <utility>
#include <vector>

namespace bimrock {

struct TrialHint {
  std::vector<int> points;                  ///< yield points of the trial's last LCP
  std::vector<std::pair<int, int>> active;  ///< (point, mode): active at its end
};

struct TrialHints {
  enum class Mode { record, replay };
  Mode mode = Mode::record;
  std::vector<TrialHint> trials;  ///< in the order the analysis tried them
  std::size_t next = 0;           ///< replay: the next trial's hint
};

}  // namespace bimrock
