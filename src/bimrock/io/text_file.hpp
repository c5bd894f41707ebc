#pragma once
/// @file Opening result files for writing, with an error that names the file.
#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace bimrock {

inline std::ofstream open_for_writing(const std::filesystem::path& file) {
  std::ofstream out(file);
  if (!out)
    throw std::runtime_error("cannot write " + file.string());
  return out;
}

/// Throws if an earlier write to `out` failed (disk full, ...).
inline void check_written(const std::ofstream& out, const std::filesystem::path& file) {
  if (!out)
    throw std::runtime_error("error while writing " + file.string());
}

}  // namespace bimrock
