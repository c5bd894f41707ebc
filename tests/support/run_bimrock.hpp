#pragma once
// Runs the bimrock command on a case text in a fresh temporary folder, as a user would.
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>

#include <sys/wait.h>

namespace bimrock::testing {

struct CommandResult {
  int exit_code = -1;
  std::string err;               // standard error
  std::string out;               // standard output
  std::filesystem::path folder;  // the temporary folder: case.yaml, results/
};

inline std::filesystem::path fresh_folder(const std::string& prefix) {
  std::random_device rd;
  const auto dir = std::filesystem::temp_directory_path() /
                   (prefix + "-" + std::to_string(rd()) + std::to_string(rd()));
  std::filesystem::create_directories(dir);
  return dir;
}

inline std::string read_text(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

/// Writes `case_text` to <tmp>/case.yaml and runs `bimrock <command> case.yaml <args>` there.
inline CommandResult run_bimrock(const std::string& command, const std::string& case_text,
                                 const std::string& args = "") {
  CommandResult r;
  r.folder = fresh_folder("bimrock-test");
  std::ofstream(r.folder / "case.yaml") << case_text;
  const std::string cmd = "cd '" + r.folder.string() + "' && '" + BIMROCK_BINARY + "' " + command +
                          " case.yaml " + args + " > stdout.txt 2> stderr.txt";
  const int status = std::system(cmd.c_str());
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.err = read_text(r.folder / "stderr.txt");
  r.out = read_text(r.folder / "stdout.txt");
  return r;
}

/// Bounds a run of the command by run_bimrock_bounded: wall time [s] and address space [bytes].
struct RunBounds {
  int seconds = 10;
  long long address_space = 1LL << 30;  // 1 GiB
};

/// run_bimrock, with the run killed after `bounds.seconds` (exit code 137: SIGKILL) and its
/// address space limited to `bounds.address_space` (an allocation beyond fails), so that a run
/// that hangs or takes unbounded memory fails the test instead of the machine. Sanitizers
/// reserve terabytes of address space, so under them only the time is bounded.
inline CommandResult run_bimrock_bounded(const std::string& command, const std::string& case_text,
                                         const std::string& args = "", RunBounds bounds = {}) {
#if defined(__SANITIZE_ADDRESS__)
  const std::string memory;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
  const std::string memory;
#else
  const std::string memory = "prlimit --as=" + std::to_string(bounds.address_space) + " -- ";
#endif
#else
  const std::string memory = "prlimit --as=" + std::to_string(bounds.address_space) + " -- ";
#endif
  CommandResult r;
  r.folder = fresh_folder("bimrock-test");
  std::ofstream(r.folder / "case.yaml") << case_text;
  const std::string cmd = "cd '" + r.folder.string() + "' && timeout -s KILL " +
                          std::to_string(bounds.seconds) + " " + memory + "'" + BIMROCK_BINARY +
                          "' " + command + " case.yaml " + args + " > stdout.txt 2> stderr.txt";
  const int status = std::system(cmd.c_str());
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.err = read_text(r.folder / "stderr.txt");
  r.out = read_text(r.folder / "stdout.txt");
  return r;
}

}  // namespace bimrock::testing
