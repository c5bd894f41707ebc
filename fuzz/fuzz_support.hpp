#pragma once
// What every fuzz target checks of an error, and where its case file "lives".
#include <cstdio>
#include <cstdlib>
#include <string>

#include <bimrock/model/errors.hpp>

namespace bimrock::fuzz {

/// The name a fuzzed case file is read under. It sits in the gmsh example's folder, so that a
/// `mesh: {file: ground.msh}` (in the seeds) resolves and the mesh half of the reader is reached.
inline const std::string& case_name() {
  static const std::string name = BIMROCK_FUZZ_CASE_NAME;
  return name;
}

/// An error must name its file: the command prints it as the one line the user gets.
inline void expect_located(const InputError& e) {
  if (e.file().empty() || e.message().empty()) {
    std::fprintf(stderr, "an InputError without a file or a message: '%s'\n", e.what());
    std::abort();
  }
}

}  // namespace bimrock::fuzz
