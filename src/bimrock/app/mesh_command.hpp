#pragma once
// `bimrock mesh`: the blocks of a case as bimrock will analyse them, written without solving
// (VTK, a picture with the joints drawn, and counts), so a user can look before running.
#include <filesystem>
#include <string>

namespace bimrock {

/// Reads and builds the case, writes OUT/blocks.vtu, OUT/blocks.png/.svg and OUT/summary.json
/// (all or nothing). Throws InputError / ModelError like `run`.
void run_mesh(const std::string& case_file, const std::filesystem::path& out, bool quiet);

}  // namespace bimrock
