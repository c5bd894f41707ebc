#pragma once
/// @file When to try a route that is cheap where it succeeds and can fail on one LCP after
/// another (the dense active block first, increment_solver.hpp): at every chance until it has
/// failed a number of times in a row, then only at every period-th chance until it succeeds
/// again.
namespace bimrock {

class RetrySchedule {
 public:
  /// @param failures failed tries in a row after which the route is tried only periodically
  /// @param period try at every period-th chance then (1: at every chance)
  RetrySchedule(int failures, int period) : failures_(failures), period_(period) {}

  /// A chance to try the route: whether to take it.
  [[nodiscard]] bool try_now() {
    if (failed_ < failures_)
      return true;
    if (++passed_ < period_)
      return false;
    passed_ = 0;
    return true;
  }
  /// What came of a try taken.
  void tried(bool succeeded) {
    failed_ = succeeded ? 0 : failed_ + 1;
    passed_ = 0;
  }

 private:
  int failures_;
  int period_;
  int failed_ = 0;  // tries failed in a row
  int passed_ = 0;  // chances passed by since the last try
};

}  // namespace bimrock
