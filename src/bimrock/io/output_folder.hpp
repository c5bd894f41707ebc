#pragma once
/// @file All-or-nothing results: files are written into a hidden sibling of the results folder
/// and renamed into place only when complete (docs/results.md), so a failed or interrupted
/// run never leaves partial or mixed results where a user looks for them.
#include <filesystem>

namespace bimrock {

class StagingFolder {
 public:
  /// Creates `<parent>/.<name>.partial-<pid>` for the results folder `target`, after removing
  /// the staging and old folders of `target` whose process is gone (a run killed with SIGKILL
  /// leaves them). Throws
  /// std::runtime_error when `target` exists but is not a results folder (it would be replaced).
  explicit StagingFolder(std::filesystem::path target);
  /// Removes the staging folder unless commit() succeeded.
  ~StagingFolder();
  StagingFolder(const StagingFolder&) = delete;
  StagingFolder& operator=(const StagingFolder&) = delete;

  /// Where to write now.
  [[nodiscard]] const std::filesystem::path& path() const { return staging_; }
  [[nodiscard]] const std::filesystem::path& target() const { return target_; }

  /// Replaces `target` by the staging folder (the old results are removed only now).
  void commit();

 private:
  std::filesystem::path target_;
  std::filesystem::path staging_;
  bool committed_ = false;
};

/// The staging folder of the StagingFolder now being written (one per process), or null: a
/// signal handler may read it to remove the folder of an interrupted run. A later run removes
/// what a killed one left, once it proves that run's process gone.
[[nodiscard]] const char* staging_in_progress();

/// Checks, before any work, that the results can be written to `folder`: it is absent, an empty
/// folder or earlier results; the nearest existing folder above it is a folder one may create
/// folders in (tried with a probe folder, removed at once). Throws InputError naming `folder`.
void check_output_folder(const std::filesystem::path& folder);

/// Whether `folder` holds results of an earlier run (a summary.json), or is empty: only such a
/// folder may be replaced by new results.
[[nodiscard]] bool is_replaceable_results_folder(const std::filesystem::path& folder);

}  // namespace bimrock
