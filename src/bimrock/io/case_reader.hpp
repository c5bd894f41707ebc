#pragma once
/// @file Reading a case file (YAML). Every error names the file, the line and the item.
/// The keys, their units and defaults are documented in docs/case-file.md.
#include <span>
#include <string>
#include <string_view>

#include <bimrock/analysis/plastic_options.hpp>
#include <bimrock/model/case_spec.hpp>

namespace bimrock {

/// What to write besides summary.json.
struct OutputOptions {
  bool vtk = true;    ///< vtk/step_NNNN.vtu + results.pvd
  int vtk_every = 1;  ///< nonlinear: a step every this many carried increments (and the last)
  bool csv = true;    ///< blocks.csv, interfaces.csv
};

struct Case {
  CaseSpec spec;
  OutputOptions output;
  PlasticOptions plastic;  ///< the analysis section's options of a plastic analysis
};

/// Reads and checks the syntax of a case file (unknown keys, types, required keys); the model
/// itself is checked by build_model(). Throws InputError.
Case read_case_file(const std::string& path);

/// The same from text; `name` stands for the file in error messages.
Case read_case_string(const std::string& text, const std::string& name);

/// A key the case file accepts. The reader takes the keys of each section from this one table,
/// and a test checks that docs/case-file.md documents every one of them.
struct CaseKey {
  /// Where the key sits: "" (top level), "analysis", "materials.<name>", "blocks[]", ...
  std::string_view section;
  std::string_view key;
  /// Required whenever its section is present. Keys required only in some forms (kn and ks of a
  /// joint material given by springs) are checked by the reader and marked false here.
  bool required = false;

  /// The documented path, e.g. "schema", "materials.<name>.E", "loads.tractions[].normal".
  [[nodiscard]] std::string path() const {
    return section.empty() ? std::string(key) : std::string(section) + "." + std::string(key);
  }
};

/// Every key of the schema (version 1), section by section in the order of docs/case-file.md.
std::span<const CaseKey> case_file_keys();

}  // namespace bimrock
