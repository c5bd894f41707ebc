#include <bimrock/io/output_folder.hpp>

#include <stdexcept>
#include <system_error>

#include <unistd.h>

#include <fmt/core.h>

namespace bimrock {

namespace fs = std::filesystem;

bool is_replaceable_results_folder(const fs::path& folder) {
  if (!fs::exists(folder))
    return true;
  if (!fs::is_directory(folder))
    return false;
  return fs::is_empty(folder) || fs::exists(folder / "summary.json");
}

StagingFolder::StagingFolder(fs::path target) : target_(std::move(target)) {
  if (target_.filename().empty())
    target_ = target_.parent_path();  // "out/" -> "out"
  if (!is_replaceable_results_folder(target_)) {
    throw std::runtime_error(fmt::format(
        "{} exists and does not hold bimrock results (no summary.json): choose another output "
        "folder or remove it",
        target_.string()));
  }
  const fs::path parent = target_.has_parent_path() ? target_.parent_path() : fs::path(".");
  fs::create_directories(parent);
  staging_ = parent / fmt::format(".{}.partial-{}", target_.filename().string(), ::getpid());
  fs::remove_all(staging_);
  fs::create_directory(staging_);
}

StagingFolder::~StagingFolder() {
  if (committed_)
    return;
  std::error_code ignored;
  fs::remove_all(staging_, ignored);
}

void StagingFolder::commit() {
  // Two renames rather than remove + rename: the old results stay until the new ones are whole.
  fs::path old;
  if (fs::exists(target_)) {
    old =
        target_.parent_path() / fmt::format(".{}.old-{}", target_.filename().string(), ::getpid());
    fs::remove_all(old);
    fs::rename(target_, old);
  }
  fs::rename(staging_, target_);
  committed_ = true;
  if (!old.empty())
    fs::remove_all(old);
}

}  // namespace bimrock
