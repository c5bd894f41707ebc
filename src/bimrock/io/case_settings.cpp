/// @file The run's settings: the analysis section (plane mode, thickness, penalty factor and the
/// options of a plastic analysis), limits and output.
#include <bimrock/io/case_sections.hpp>

#include <algorithm>

#include <string>
#include <utility>
#include <vector>

#include <fmt/core.h>

namespace bimrock::case_file {

AnalysisSettings read_analysis(const Value& v) {
  const Map m = open(v, "analysis");
  AnalysisSettings s;
  if (const auto plane = m.find("plane"))
    s.plane =
        choice<PlaneMode>(*plane, {{"strain", PlaneMode::strain}, {"stress", PlaneMode::stress}});
  if (const auto t = m.find("thickness"))
    s.thickness = positive(*t);
  if (const auto p = m.find("penalty_factor"))
    s.penalty_factor = positive(*p);
  return s;
}

/// The analysis section's options of a plastic analysis (docs/case-file.md), each in its range.
PlasticOptions read_plastic_options(const Value& v) {
  const Map m = open(v, "analysis");
  PlasticOptions o;
  const auto fraction = [&](const char* key, double& field, double most) {
    if (const auto x = m.find(key)) {
      field = positive(*x);
      if (field > most)
        x->fail(fmt::format("must be at most {}", most));
    }
  };
  const auto count = [&](const char* key, int& field, int most) {
    if (const auto x = m.find(key)) {
      field = x->integer();
      if (field < 1 || field > most)
        x->fail(fmt::format("must be a whole number from 1 to {}", most));
    }
  };
  fraction("bracket_tolerance", o.bracket_tolerance, 0.5);
  fraction("yield_tolerance", o.yield_tolerance, 1e-3);
  count("max_bisections", o.max_bisections, 200);
  count("max_rounds", o.max_rounds, 1000);
  return o;
}

/// factor_of_safety: the materials whose strength is reduced (names of materials or joint
/// materials with a strength law; default every one), the bracket's relative tolerance, the
/// step of F between trials and the largest F tried.
FactorOfSafetyOptions read_factor_of_safety(const Value& v, const CaseSpec& spec) {
  const Map m = open(v, "factor_of_safety");
  FactorOfSafetyOptions o;
  if (const auto x = m.find("tolerance")) {
    o.tolerance = positive(*x);
    if (o.tolerance > 0.1)
      x->fail("must be at most 0.1");
  }
  if (const auto x = m.find("step")) {
    o.step = positive(*x);
    if (o.step > 10.0)
      x->fail("must be at most 10");
  }
  if (const auto x = m.find("largest")) {
    o.largest = positive(*x);
    if (o.largest <= 1.0 || o.largest > 1000.0)
      x->fail("must be above 1 and at most 1000 (F = 1 is the state the stages reach)");
  }
  if (const auto x = m.find("materials")) {
    o.selection.joint_materials.assign(spec.joint_materials.size(), 0);
    o.selection.block_materials.assign(spec.block_materials.size(), 0);
    const std::vector<Value> items = x->list();
    std::vector<std::string> names;
    for (const Value& item : items)
      names.push_back(name(item));
    for (std::size_t k = 0; k < names.size(); ++k) {
      bool found = false;
      for (std::size_t j = 0; j < spec.joint_materials.size(); ++j)
        if (spec.joint_materials[j].name == names[k]) {
          if (!spec.joint_materials[j].strength)
            items[k].fail("joint material '" + names[k] + "' has no strength to reduce");
          o.selection.joint_materials[j] = 1;
          found = true;
        }
      for (std::size_t b = 0; b < spec.block_materials.size(); ++b)
        if (spec.block_materials[b].name == names[k]) {
          if (!spec.block_materials[b].strength)
            items[k].fail("material '" + names[k] + "' has no strength to reduce");
          o.selection.block_materials[b] = 1;
          found = true;
        }
      if (!found)
        items[k].fail("'" + names[k] + "' is neither a material nor a joint material");
    }
    if (names.empty())
      x->fail("name at least one material, or leave the key out to reduce every strength");
  }
  if (const auto x = m.find("after_stage")) {
    const std::string stage = name(*x);
    const auto named = std::find_if(spec.stages.begin(), spec.stages.end(),
                                    [&](const StageSpec& st) { return st.name == stage; });
    if (named == spec.stages.end())
      x->fail("no stage is named '" + stage + "'");
    o.after_stage = static_cast<int>(named - spec.stages.begin());
  }
  return o;
}

/// limits: each a positive number (a count, or MB for output_mb).
CaseLimits read_limits(const Value& v) {
  const Map m = open(v, "limits");
  CaseLimits l;
  const std::pair<const char*, double*> fields[] = {
      {"blocks", &l.blocks},         {"joint_traces", &l.joint_traces},
      {"interfaces", &l.interfaces}, {"yield_planes", &l.yield_planes},
      {"increments", &l.increments}, {"output_mb", &l.output_mb}};
  for (const auto& [key, field] : fields) {
    if (const auto x = m.find(key)) {
      *field = positive(*x);
      l.lines[std::string("limits.") + key] = x->line();
    }
  }
  return l;
}

OutputOptions read_output(const Value& v) {
  const Map m = open(v, "output");
  OutputOptions o;
  o.vtk = m.boolean_or("vtk", o.vtk);
  if (const auto every = m.find("vtk_every")) {
    o.vtk_every = every->integer();
    if (o.vtk_every < 1)
      every->fail("must be at least 1");
  }
  o.csv = m.boolean_or("csv", o.csv);
  return o;
}

}  // namespace bimrock::case_file
