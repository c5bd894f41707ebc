// The bimrock command line: `run` a case, `check` a case without solving.
// Errors a user can cause (InputError, ModelError) are caught here, once, and reported as one
// clear message with a non-zero exit; nothing is written to the output folder then.
#include <csignal>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <optional>
#include <string>

#include <unistd.h>

#include <fmt/core.h>
#include <CLI/CLI.hpp>

#include <bimrock/analysis/elastic_analysis.hpp>
#include <bimrock/analysis/plastic_analysis.hpp>
#include <bimrock/io/case_reader.hpp>
#include <bimrock/io/output_folder.hpp>
#include <bimrock/io/results_writer.hpp>
#include <bimrock/solve/factor_memory.hpp>

#ifdef BIMROCK_WITH_PETSC
#include <bimrock/petsc/distributed_factor.hpp>
#include <bimrock/petsc/elastic_solve.hpp>
#include <bimrock/petsc/runtime.hpp>
#endif

#include "bimrock/app/bench_command.hpp"
#include "bimrock/app/mesh_command.hpp"
#include "bimrock/app/mpi_launch.hpp"
#include "bimrock/app/openmp_environment.hpp"
#include "bimrock/app/report.hpp"

namespace {

// Ctrl-C and SIGTERM: the results of an interrupted run are never written (they are staged), and
// its staging folder is removed by a shell that the handler becomes (execve is
// async-signal-safe; removing a tree is not), which exits with 128 + the signal, as a shell's
// interrupted command does.
void on_interrupt(int signal) {
  const char* staging = bimrock::staging_in_progress();
  if (staging != nullptr) {
    const char* argv[] = {"sh",   "-c",    "rm -rf -- \"$1\"; exit \"$2\"",
                          "sh",   staging, signal == SIGINT ? "130" : "143",
                          nullptr};
    ::execv("/bin/sh", const_cast<char* const*>(argv));
  }
  ::_exit(128 + signal);
}

enum ExitCode { kOk = 0, kInputError = 2, kModelError = 3, kInternalError = 4, kStopped = 5 };

// results/<folder of the case>/<case name>: the examples are all named case.yaml, and their
// results must not overwrite each other. A case in the working folder: results/<case name>.
std::filesystem::path default_output(const std::string& case_file) {
  const std::filesystem::path path(case_file);
  const std::filesystem::path folder = path.parent_path().filename();
  const bool named = !folder.empty() && folder != "." && folder != "..";
  return std::filesystem::path("results") / (named ? folder / path.stem() : path.stem());
}

// A staged case's analysis (run_plastic_analysis with `tuning`); the results are written and
// printed where `writes` (the first process of an MPI run, the only one of a serial run).
int run_stages(const std::string& case_file, const bimrock::Case& c, const bimrock::Model& model,
               const std::filesystem::path& out, bool quiet, const bimrock::PlasticTuning& tuning,
               bool writes) {
  quiet = quiet || !writes;
  if (!quiet)
    bimrock::print_model(model);  // the size first: the analysis may take a while
  std::optional<bimrock::PlasticResultsWriter> writer;
  if (writes)
    writer.emplace(model, c.output, out);
  double elapsed = 0.0;
  const bimrock::PlasticResult result = bimrock::run_plastic_analysis(
      model, c.plastic,
      [&](const bimrock::IncrementRecord& r, const bimrock::AnalysisState& s) {
        if (writer)
          writer->on_increment(r, s);
        elapsed += r.seconds;
        if (!quiet)
          bimrock::print_increment(model, r, elapsed);
      },
      tuning);
  if (writer) {
    const bimrock::ElasticSolution fields = writer->finish(result);
    if (!quiet)
      bimrock::print_plastic_summary(model, result, fields, out);
  }
  if (result.stopped) {
    if (writes)
      fmt::print(stderr, "error: {}: stage '{}' stopped at factor {}: {}\n", case_file,
                 model.stages[static_cast<std::size_t>(result.stopped->stage)].name,
                 result.stopped->factor, result.stopped->reason);
    return kStopped;
  }
  return kOk;
}

// `run --solver petsc` (docs/parallel.md): the case solved with PETSc by every process of an MPI
// run (mpirun -n N bimrock run ...); the first writes the results and prints. An elastic case
// by conjugate gradients with multigrid, a staged one on K factorized by MUMPS.
int run_with_petsc([[maybe_unused]] const std::string& case_file, const bimrock::Case& c,
                   const bimrock::Model& model, const std::filesystem::path& out, bool quiet) {
#ifdef BIMROCK_WITH_PETSC
  const bimrock::PetscRuntime petsc;
  const bool writes = petsc.rank() == 0;
  if (!model.stages.empty()) {
    if (writes && !quiet)
      fmt::print("PETSc: K factorized by MUMPS on {} process{}\n", petsc.ranks(),
                 petsc.ranks() == 1 ? "" : "es");
    bimrock::PlasticTuning tuning;
    tuning.stiffness = bimrock::distributed_factorization(model);
    return run_stages(case_file, c, model, out, quiet, tuning, writes);
  }
  bimrock::PetscSolveReport report;
  const bimrock::ElasticSolution solution = bimrock::solve_elastic_with_petsc(model, report);
  if (!writes)
    return kOk;
  bimrock::write_elastic_results(model, solution, c.output, out);
  if (!quiet) {
    bimrock::print_summary(model, solution, out);
    fmt::print("PETSc: {} on {} process{}, {} iterations, relative residual {:.2e}\n",
               report.method, report.ranks, report.ranks == 1 ? "" : "es", report.iterations,
               report.relative_residual);
    if (!report.fallback.empty())
      fmt::print("  ({}: K was factorized by MUMPS instead)\n", report.fallback);
  }
  return kOk;
#else
  (void)c, (void)model, (void)out, (void)quiet;
  throw bimrock::InputError(case_file, 0, "--solver petsc",
                            "this bimrock was built without PETSc (install libpetsc-real-dev "
                            "and rebuild; docs/parallel.md)");
#endif
}

int run(const std::string& case_file, std::filesystem::path out, const std::string& solver,
        bool quiet) {
  bimrock::Case c = bimrock::read_case_file(case_file);
  const bimrock::Model model = bimrock::build_model(c.spec);
  if (out.empty())
    out = default_output(case_file);
  // Both checked before solving: a run must not end, after the work, on a folder it cannot use.
  bimrock::check_output_size(model, c);
  bimrock::check_output_folder(out);
  // The model holds the blocks now: the case's list of them is not kept through the analysis
  // (some 180 MiB at 10^6 blocks).
  std::vector<bimrock::BlockSpec>().swap(c.spec.blocks);
  if (solver == "petsc")
    return run_with_petsc(case_file, c, model, out, quiet);
  if (model.stages.empty()) {
    const bimrock::ElasticSolution solution = bimrock::solve_elastic(model);
    bimrock::write_elastic_results(model, solution, c.output, out);
    if (!quiet)
      bimrock::print_summary(model, solution, out);
    return kOk;
  }
  return run_stages(case_file, c, model, out, quiet, {}, true);
}

int check(const std::string& case_file, bool quiet) {
  const bimrock::Case c = bimrock::read_case_file(case_file);
  const bimrock::Model model = bimrock::build_model(c.spec);
  if (!quiet) {
    bimrock::print_model(model);
    bimrock::print_memory_estimate(model);
  }
  return kOk;
}

}  // namespace

int main(int argc, char** argv) {
  bimrock::ensure_openmp_environment(argv);
  bimrock::install_factor_memory();  // the process's settings are the command's to make
  std::signal(SIGINT, on_interrupt);
  std::signal(SIGTERM, on_interrupt);
  CLI::App app{"bimrock: block-interfaces model of jointed rock masses (SI units)"};
  app.require_subcommand(1);
  app.set_version_flag("--version", std::string("bimrock ") + BIMROCK_VERSION);
  // The subcommands pass the options they do not know to the command: -q anywhere.
  app.fallthrough();
  bool quiet = false;
  app.add_flag("-q,--quiet", quiet, "print nothing but errors");

  std::string case_file;
  std::string output;
  CLI::App* run_cmd = app.add_subcommand("run", "solve a case and write its results");
  run_cmd->add_option("case", case_file, "case file (YAML)")->required();
  run_cmd->add_option("-o,--output", output,
                      "results folder (default results/<folder of the case>/<case name>)");
  std::string solver = "cholmod";
  run_cmd
      ->add_option("--solver", solver,
                   "cholmod (default), or petsc: the case with PETSc, under mpirun too "
                   "(docs/parallel.md)")
      ->check(CLI::IsMember({"cholmod", "petsc"}));

  CLI::App* check_cmd = app.add_subcommand("check", "read and check a case without solving it");
  check_cmd->add_option("case", case_file, "case file (YAML)")->required();

  CLI::App* mesh_cmd = app.add_subcommand(
      "mesh", "build the blocks of a case and write them (VTK, picture) without solving");
  mesh_cmd->add_option("case", case_file, "case file (YAML)")->required();
  mesh_cmd->add_option("-o,--output", output,
                       "folder (default results/<folder of the case>/<case name>-mesh)");

  bimrock::BenchOptions bench;
  CLI::App* bench_cmd = app.add_subcommand(
      "bench",
      "time whole analyses of generated models against CHOLMOD alone (docs/performance.md)");
  bench_cmd
      ->add_option("--models", bench.models,
                   "elastic, plastic, nonassociated, fos (the plastic model's factor of safety)")
      ->delimiter(',')
      ->check(CLI::IsMember({"elastic", "plastic", "nonassociated", "fos"}));
  bench_cmd->add_option("--elastic-sizes", bench.elastic_sizes, "blocks of the elastic brick mass")
      ->delimiter(',');
  bench_cmd
      ->add_option("--plastic-sizes", bench.plastic_sizes, "blocks of the plastic abutment model")
      ->delimiter(',');
  bench_cmd
      ->add_option("--repetitions", bench.repetitions, "runs per size (the median is reported)")
      ->check(CLI::PositiveNumber);
  bench_cmd
      ->add_option("--increments", bench.increments, "increments of the abutment's loading stage")
      ->check(CLI::PositiveNumber);
  bench_cmd
      ->add_option("--solver", bench.solver,
                   "cholmod (default), or petsc: the models with PETSc, under mpirun too "
                   "(docs/parallel.md)")
      ->check(CLI::IsMember({"cholmod", "petsc"}));
  bench_cmd->add_flag("!--no-limit", bench.limit,
                      "do not measure CHOLMOD alone beside each run (a model whose factor would "
                      "not fit in memory beside the run)");
  bench_cmd->add_option("--json", bench.json, "also write the table as JSON to this file");
  bench_cmd->add_option("--plot", bench.plot,
                        "write bench_time and bench_memory plots (PNG, SVG) to this folder");

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // --help and --version end here with 0; a command line that cannot be read is bad input.
    return app.exit(e) == 0 ? kOk : kInputError;
  }
  // Under an MPI launcher, only the PETSc backend shares the work among the processes.
  const bool serial_solver =
      (*run_cmd && solver != "petsc") || (*bench_cmd && bench.solver != "petsc");
  if (serial_solver && bimrock::launched_processes() > 1) {
    if (bimrock::launched_rank() == 0)
      fmt::print(stderr,
                 "error: started as one of {} processes by an MPI launcher (mpirun) without "
                 "--solver petsc: each would solve the whole case alone and write the same "
                 "results; add --solver petsc (docs/parallel.md), or start it without mpirun\n",
                 bimrock::launched_processes());
    return kInputError;
  }
  try {
    if (*run_cmd)
      return run(case_file, output, solver, quiet);
    if (*check_cmd)
      return check(case_file, quiet);
    if (*bench_cmd)
      return bimrock::run_bench(bench);
    if (*mesh_cmd) {
      const std::filesystem::path out =
          output.empty() ? std::filesystem::path(default_output(case_file).string() + "-mesh")
                         : std::filesystem::path(output);
      if (!bimrock::is_replaceable_results_folder(out)) {
        fmt::print(stderr,
                   "error: {}: exists and does not hold bimrock results (no summary.json); "
                   "choose another output folder\n",
                   out.string());
        return kInputError;
      }
      bimrock::run_mesh(case_file, out, quiet);
      return kOk;
    }
  } catch (const bimrock::InputError& e) {
    fmt::print(stderr, "error: {}\n", e.what());
    return kInputError;
  } catch (const bimrock::ModelError& e) {
    fmt::print(stderr, "error: {}: {}\n", case_file, e.what());
    return kModelError;
  } catch (const std::exception& e) {
    fmt::print(stderr, "internal error: {} (please report it with the case file)\n", e.what());
    return kInternalError;
  }
  return kOk;
}
