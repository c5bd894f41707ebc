// bimrock_lcp_table: our LCP solvers against Siconos Numerics' on dense LCPs of our own models
// (bench/model_lcps.hpp), the table of docs/performance.md. For each LCP it times our
// primal-dual active-set method, our Lemke, Siconos' Lemke and Siconos' Newton-min/FB (medians
// of at least --repetitions solves each, more for the fast ones) and compares every solution with
// ours (the route of the analysis: the active set's, else Lemke's on a working set of rows,
// else Lemke's on the whole LCP). A solver that claims success but differs
// from ours by more than 1e-9 relative makes the exit code 1.
//
//   bimrock_lcp_table [--repetitions N] [--brick B,...] [--wall W,...] [--wall-limit W,...] [--raw]
//
// B and W are block counts of the brick mass (model (a)), the wall near collapse (b) and the
// wall at its limit load (c) of model_lcps.hpp; 0 skips a model. "ours" is the analysis' route: the
// active-set method, then Lemke on a working set of rows, then Lemke on the whole LCP. Siconos is
// given the LCP equilibrated by powers of two (see SiconosLcp); --raw gives it the unscaled one
// instead. Details of every solve go to stderr, the markdown table to stdout.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <memory>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <bimrock/solve/active_set_lcp.hpp>
#include <bimrock/solve/lemke.hpp>
#include <bimrock/solve/working_set_lcp.hpp>

#include "bimrock/app/openmp_environment.hpp"

#include "model_lcps.hpp"
#include "siconos_lcp.hpp"

namespace bimrock::bench {
namespace {

struct Options {
  int repetitions = 3;
  std::vector<int> brick{100, 400, 700, 1000};
  std::vector<int> wall{100, 160, 290, 460};
  std::vector<int> wall_limit{100, 160, 290, 460};
  bool raw = false;  // give Siconos the unscaled LCP
};

std::vector<int> parse_list(const char* text) {
  std::vector<int> values;
  std::stringstream in(text);
  std::string item;
  while (std::getline(in, item, ','))
    if (const int v = std::atoi(item.c_str()); v > 0)
      values.push_back(v);
  return values;
}

Options parse(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const bool has_value = i + 1 < argc;
    if (!std::strcmp(argv[i], "--repetitions") && has_value) {
      o.repetitions = std::max(1, std::atoi(argv[++i]));
    } else if (!std::strcmp(argv[i], "--brick") && has_value) {
      o.brick = parse_list(argv[++i]);
    } else if (!std::strcmp(argv[i], "--wall") && has_value) {
      o.wall = parse_list(argv[++i]);
    } else if (!std::strcmp(argv[i], "--wall-limit") && has_value) {
      o.wall_limit = parse_list(argv[++i]);
    } else if (!std::strcmp(argv[i], "--raw")) {
      o.raw = true;
    } else {
      std::fprintf(stderr,
                   "usage: %s [--repetitions N] [--brick B,...] [--wall W,...] [--wall-limit "
                   "W,...] [--raw]\n",
                   argv[0]);
      std::exit(2);
    }
  }
  return o;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

// One solver on one LCP: the median time and the last result.
struct Timed {
  double seconds = 0.0;
  int solves = 0;
  LcpResult result;
};

// At least `repetitions` solves, more for fast solvers until they add up to a second (at most
// 50): medians of milliseconds need more than three samples.
Timed time_solver(LcpSolver& solver, const ModelLcp& lcp, int repetitions) {
  const Eigen::VectorXd* warm = lcp.warm_start.size() > 0 ? &lcp.warm_start : nullptr;
  Timed t;
  std::vector<double> seconds;
  double total = 0.0;
  while (static_cast<int>(seconds.size()) < repetitions || (total < 1.0 && seconds.size() < 50)) {
    const auto start = std::chrono::steady_clock::now();
    t.result = solver.solve(lcp.problem, warm);
    seconds.push_back(
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    total += seconds.back();
  }
  t.seconds = median(seconds);
  t.solves = static_cast<int>(seconds.size());
  return t;
}

std::string seconds_cell(const Timed& t) {
  char cell[64];
  std::snprintf(cell, sizeof cell, "%.3g", t.seconds);
  std::string s = cell;
  if (t.result.status != LcpStatus::solved)
    s += std::string(" (") + to_string(t.result.status) + ")";
  return s;
}

// Prints the row of one LCP; returns false when a solver claimed success and disagrees with ours.
bool report(const ModelLcp& lcp, int repetitions, bool equilibrate) {
  ActiveSetLcp active_set;
  Lemke lemke;
  SiconosLcp siconos_lemke(SiconosMethod::lemke, equilibrate);
  SiconosLcp siconos_newton(SiconosMethod::newton_min_fb, equilibrate);
  LcpSolver* solvers[] = {&active_set, &lemke, &siconos_lemke, &siconos_newton};
  Timed runs[4];
  for (int k = 0; k < 4; ++k) {
    runs[k] = time_solver(*solvers[k], lcp, repetitions);
    std::fprintf(stderr,
                 "  %-22s %10.4g s (median of %d)  %s, %d steps, worst relative residual %.2g\n",
                 solvers[k]->name().c_str(), runs[k].seconds, runs[k].solves,
                 to_string(runs[k].result.status), runs[k].result.steps,
                 runs[k].result.residuals.worst_relative());
  }
  // Ours as the analysis solves an increment: the active-set method, then Lemke on a working
  // set of rows where it fails (plastic_analysis.cpp), then Lemke on the whole LCP.
  const bool fell_back = runs[0].result.status != LcpStatus::solved;
  Timed working_set;
  if (fell_back) {
    std::vector<Eigen::Index> initial;
    const Eigen::VectorXd& z = runs[0].result.z;
    for (Eigen::Index i = 0; i < lcp.problem.size(); ++i)
      if ((lcp.warm_start.size() > 0 && lcp.warm_start(i) > 0.0) ||
          (z.size() == lcp.problem.size() && z(i) > 0.0))
        initial.push_back(i);
    std::vector<double> seconds;
    while (static_cast<int>(seconds.size()) < repetitions) {
      DenseLcpColumns columns(lcp.problem);
      const auto start = std::chrono::steady_clock::now();
      working_set.result = solve_on_working_set(columns, initial, lemke);
      seconds.push_back(
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    }
    working_set.seconds = median(seconds);
    std::fprintf(stderr, "  working set (from %zu rows) %8.4g s  %s, %d pivots\n", initial.size(),
                 working_set.seconds, to_string(working_set.result.status),
                 working_set.result.steps);
  }
  const bool working_set_solved = working_set.result.status == LcpStatus::solved;
  const Timed& ours = !fell_back ? runs[0] : working_set_solved ? working_set : runs[1];
  const double ours_seconds = runs[0].seconds + (fell_back ? working_set.seconds : 0.0) +
                              (fell_back && !working_set_solved ? runs[1].seconds : 0.0);
  bool agree = true;
  double worst = 0.0;
  std::string notes = !fell_back           ? ""
                      : working_set_solved ? "active set failed, ours = working-set Lemke"
                                           : "active set and working set failed, ours = Lemke";
  auto note = [&notes](const std::string& n) { notes += (notes.empty() ? "" : "; ") + n; };
  if (ours.result.status != LcpStatus::solved) {
    note("ours: no solution found");
  } else {
    for (int k = 0; k < 4; ++k) {
      if (runs[k].result.status != LcpStatus::solved) {
        if (k > 0)
          note(solvers[k]->name() + ": " + to_string(runs[k].result.status));
        continue;
      }
      const SolutionDifference d = compare_solutions(runs[k].result.z, ours.result.z);
      std::fprintf(stderr, "  %-22s differs from ours by %.2g relative, %.2g scaled (brief)\n",
                   solvers[k]->name().c_str(), d.relative, d.scaled);
      worst = std::max(worst, d.relative);
      if (d.relative > kAgreement) {
        agree = false;
        note(solvers[k]->name() + " disagrees");
      }
    }
  }
  std::printf("| %s | %d | %d | %s | %s | %.3g | %s | %s | %.0f | %.1f | %.0e | %s |\n",
              lcp.model.c_str(), lcp.blocks, static_cast<int>(lcp.problem.size()),
              seconds_cell(runs[0]).c_str(), seconds_cell(runs[1]).c_str(), ours_seconds,
              seconds_cell(runs[2]).c_str(), seconds_cell(runs[3]).c_str(),
              runs[2].seconds / ours_seconds, runs[2].seconds / runs[1].seconds, worst,
              notes.empty() ? "-" : notes.c_str());
  std::fflush(stdout);
  return agree;
}

}  // namespace
}  // namespace bimrock::bench

int main(int argc, char** argv) {
  bimrock::ensure_openmp_environment(argv);
  using namespace bimrock::bench;
  const Options o = parse(argc, argv);
  std::printf(
      "LCP solvers on dense LCPs of our own models: medians of at least %d solves (more until "
      "1 s), %u cores, Siconos given the %s LCP\n\n",
      o.repetitions, std::thread::hardware_concurrency(), o.raw ? "unscaled" : "equilibrated");
  std::printf(
      "| model | blocks | rows | active set s | our Lemke s | ours s | Siconos Lemke s | Siconos "
      "Newton-min-FB s | speed-up: Siconos Lemke / ours | Siconos Lemke / our Lemke | max rel. "
      "difference | notes |\n|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  bool agree = true;
  auto run = [&](ModelLcp (*make)(int), int blocks) {
    const auto start = std::chrono::steady_clock::now();
    ModelLcp lcp;
    try {
      lcp = make(blocks);
    } catch (const std::exception& e) {
      std::printf("| %d blocks: %s |\n", blocks, e.what());
      agree = false;
      return;
    }
    std::fprintf(stderr,
                 "%s: %d rows (the analysis' own LCP: %d rows, %d active-set iterations, %d "
                 "Lemke pivots), %s M, built in %.1f s\n",
                 lcp.source.c_str(), static_cast<int>(lcp.problem.size()), lcp.analysis_rows,
                 lcp.analysis_active_set_iterations, lcp.analysis_pivots,
                 lcp.symmetric ? "symmetric" : "non-symmetric",
                 std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    agree = report(lcp, o.repetitions, !o.raw) && agree;
  };
  for (int b : o.brick)
    run(brick_mass_gravity_lcp, b);
  for (int b : o.wall)
    run(wall_near_collapse_lcp, b);
  for (int b : o.wall_limit)
    run(wall_at_limit_lcp, b);
  return agree ? 0 : 1;
}
