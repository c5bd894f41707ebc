#pragma once
/// @file Wall-clock time per named phase of an analysis.
#include <algorithm>
#include <chrono>
#include <cstdint>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include <bimrock/analysis/memory_probe.hpp>

namespace bimrock {

struct Timings {
  /// (phase, seconds), in order; a phase in parentheses is a part of others, not summed.
  std::vector<std::pair<std::string, double>> phases;
  /// With memory_tracking() on, ScopedTimer also records each phase's peak resident memory
  /// (bytes) here.
  std::map<std::string, std::int64_t> peak_bytes;

  void add(const std::string& phase, double seconds) {
    for (auto& [name, s] : phases) {
      if (name == phase) {
        s += seconds;
        return;
      }
    }
    phases.emplace_back(phase, seconds);
  }
  [[nodiscard]] double total() const {
    double t = 0.0;
    for (const auto& [name, seconds] : phases)
      if (name.empty() || name.front() != '(')
        t += seconds;
    return t;
  }
};

/// Times a scope: `{ ScopedTimer t(timings, "assemble"); ... }`.
class ScopedTimer {
 public:
  ScopedTimer(Timings& timings, std::string phase) : timings_(timings), phase_(std::move(phase)) {
    if (memory_tracking())
      reset_peak_memory();
    start_ = std::chrono::steady_clock::now();
  }
  ~ScopedTimer() {
    timings_.add(phase_,
                 std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count());
    if (memory_tracking()) {
      std::int64_t& peak = timings_.peak_bytes[phase_];
      peak = std::max(peak, peak_memory_bytes());
    }
  }
  ScopedTimer(const ScopedTimer&) = delete;
  ScopedTimer& operator=(const ScopedTimer&) = delete;

 private:
  Timings& timings_;
  std::string phase_;
  std::chrono::steady_clock::time_point start_;
};

/// Splits a stretch of code into consecutive phases: `lap("a")` charges the time since the
/// previous lap (or construction) to phase "a". Null timings: does nothing.
class LapTimer {
 public:
  explicit LapTimer(Timings* timings)
      : timings_(timings), last_(std::chrono::steady_clock::now()) {}
  void lap(const std::string& phase) {
    if (!timings_)
      return;
    const auto now = std::chrono::steady_clock::now();
    timings_->add(phase, std::chrono::duration<double>(now - last_).count());
    last_ = now;
  }
  /// As lap(phase), but `part_seconds` of the time (measured inside it) go to phase `part`.
  void lap(const std::string& phase, const std::string& part, double part_seconds) {
    if (!timings_)
      return;
    const auto now = std::chrono::steady_clock::now();
    const double all = std::chrono::duration<double>(now - last_).count();
    timings_->add(part, part_seconds);
    timings_->add(phase, std::max(0.0, all - part_seconds));
    last_ = now;
  }

 private:
  Timings* timings_;
  std::chrono::steady_clock::time_point last_;
};

}  // namespace bimrock
