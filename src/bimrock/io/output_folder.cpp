#include <bimrock/io/output_folder.hpp>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <string>
#include <system_error>

#include <signal.h>
#include <unistd.h>

#include <fmt/core.h>

#include <bimrock/model/errors.hpp>

namespace bimrock {

namespace fs = std::filesystem;

bool is_replaceable_results_folder(const fs::path& folder) {
  if (!fs::exists(folder))
    return true;
  if (!fs::is_directory(folder))
    return false;
  return fs::is_empty(folder) || fs::exists(folder / "summary.json");
}

void check_output_folder(const fs::path& folder) {
  fs::path target = folder;
  if (target.filename().empty())
    target = target.parent_path();  // "out/" -> "out"
  const auto fail = [&](const std::string& why) {
    throw InputError(target.string(), 0, "", "cannot write the results here: " + why);
  };
  std::error_code ec;
  const fs::file_status status = fs::status(target, ec);
  if (fs::exists(status)) {
    if (!fs::is_directory(status))
      fail("it exists and is not a folder; choose another output folder (-o)");
    if (!is_replaceable_results_folder(target)) {
      fail(
          "it exists and does not hold bimrock results (no summary.json); choose another "
          "output folder (-o) or remove it");
    }
  }
  // The results are staged beside the target, in its parent, created if need be: the nearest
  // existing ancestor must be a folder we may create folders in.
  fs::path above = target.has_parent_path() ? target.parent_path() : fs::path(".");
  while (!fs::exists(above, ec) && above.has_parent_path() && above != above.parent_path())
    above = above.parent_path();
  if (!fs::exists(above, ec))
    above = ".";
  if (!fs::is_directory(above, ec))
    fail(above.string() + " is not a folder");
  const fs::path probe = above / fmt::format(".bimrock-probe-{}", ::getpid());
  if (!fs::create_directory(probe, ec) || ec)
    fail("cannot create a folder in " + above.string() + ": " + ec.message());
  fs::remove(probe, ec);
}

namespace {

/// The staging folder being written, for a signal handler (staging_in_progress()).
char g_staging[4096];
std::atomic<bool> g_staging_set{false};

/// The pid of a `.<name>.partial-<pid>` or `.<name>.old-<pid>` sibling of `target`, or 0.
long sibling_pid(const fs::path& entry, const std::string& name) {
  const std::string file = entry.filename().string();
  for (const char* kind : {".partial-", ".old-"}) {
    const std::string prefix = "." + name + kind;
    if (file.rfind(prefix, 0) == 0 && file.size() > prefix.size()) {
      const std::string digits = file.substr(prefix.size());
      if (digits.find_first_not_of("0123456789") != std::string::npos || digits.size() > 9)
        return 0;
      return std::stol(digits);
    }
  }
  return 0;
}

/// Removes the staging and old folders of `target` left by runs that were killed: only where
/// their process is proven gone (kill(pid, 0) fails with ESRCH), never a live run's.
void remove_stale_siblings(const fs::path& parent, const std::string& name) {
  std::error_code ec;
  for (fs::directory_iterator it(parent, ec), end; !ec && it != end; it.increment(ec)) {
    const long pid = sibling_pid(it->path(), name);
    if (pid <= 0 || pid == ::getpid())
      continue;
    if (::kill(static_cast<pid_t>(pid), 0) == -1 && errno == ESRCH) {
      std::error_code ignored;
      fs::remove_all(it->path(), ignored);
    }
  }
}

}  // namespace

const char* staging_in_progress() {
  return g_staging_set.load() ? g_staging : nullptr;
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
  remove_stale_siblings(parent, target_.filename().string());
  staging_ = parent / fmt::format(".{}.partial-{}", target_.filename().string(), ::getpid());
  fs::remove_all(staging_);
  fs::create_directory(staging_);
  const std::string path = staging_.string();
  if (path.size() < sizeof g_staging) {
    std::memcpy(g_staging, path.c_str(), path.size() + 1);
    g_staging_set = true;
  }
}

StagingFolder::~StagingFolder() {
  g_staging_set = false;
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
  g_staging_set = false;
  if (!old.empty())
    fs::remove_all(old);
}

}  // namespace bimrock
