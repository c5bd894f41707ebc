#pragma once
/// @file Reading a case file (YAML). Every error names the file, the line and the item.
/// The keys, their units and defaults are documented in docs/case-file.md.
#include <string>

#include <bimrock/model/case_spec.hpp>

namespace bimrock {

/// What to write besides summary.json.
struct OutputOptions {
  bool vtk = true;  ///< vtk/step_NNNN.vtu + results.pvd
  bool csv = true;  ///< blocks.csv, interfaces.csv
};

struct Case {
  CaseSpec spec;
  OutputOptions output;
};

/// Reads and checks the syntax of a case file (unknown keys, types, required keys); the model
/// itself is checked by build_model(). Throws InputError.
Case read_case_file(const std::string& path);

/// The same from text; `name` stands for the file in error messages.
Case read_case_string(const std::string& text, const std::string& name);

}  // namespace bimrock
