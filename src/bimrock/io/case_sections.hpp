#pragma once
/// @file The sections of a case file, one reader each (internal to the case reader, which puts
/// them together in read_document()). Each opens its map against its keys in the schema's key
/// table, so that unknown, repeated and missing keys are refused before its values are read.
/// Everything that needs the whole model (convexity, overlaps, material names, positive
/// stiffness) is left to build_model(). The readers are documented at their definitions, in the
/// file named above each group.
#include <string_view>
#include <vector>

#include <bimrock/analysis/plastic_options.hpp>
#include <bimrock/io/case_reader.hpp>
#include <bimrock/io/case_values.hpp>
#include <bimrock/io/gmsh_mesh.hpp>
#include <bimrock/model/case_spec.hpp>

namespace bimrock::case_file {

// case_keys.cpp: the schema's key table.
std::vector<std::string_view> keys_of(std::string_view section);
void require_keys(const Map& m, std::string_view section);
Map open(const Value& v, std::string_view section);

// case_selector.cpp: where a joint rule, support or traction applies; which blocks a stage
// excavates or installs.
Selector read_selector(const Map& m, const char* kinds);
BlockSelector read_block_selector(const Value& v, std::string_view section);

// case_settings.cpp: analysis, limits, output.
AnalysisSettings read_analysis(const Value& v);
PlasticOptions read_plastic_options(const Value& v);
FactorOfSafetyOptions read_factor_of_safety(const Value& v, const CaseSpec& spec);
CaseLimits read_limits(const Value& v);
OutputOptions read_output(const Value& v);

// case_materials.cpp: materials, joint_materials.
BlockMaterial read_block_material(const Entry& e);
JointMaterial read_joint_material(const Entry& e, const AnalysisSettings& settings);

// case_geometry.cpp: blocks, domain, joints.
BlockSpec read_block(const Value& v);
DomainSpec read_domain(const Value& v);
void read_joints(const Value& v, CaseSpec& spec);

// case_mesh.cpp: mesh, and the group selectors it resolves.
MeshSpec read_mesh(const Value& v, GmshMesh& mesh);
void resolve_groups(CaseSpec& s, const GmshMesh* mesh);

// case_loading.cpp: supports, loads, stages.
SupportSpec read_support(const Value& v);
LoadsSpec read_loads(const Value& v);
std::vector<StageSpec> read_stages(const Value& v);

// case_initial_stress.cpp: initial_stress.
InitialStressSpec read_initial_stress(const Value& v);

// case_bolts.cpp: bolts.
std::vector<BoltSpec> read_bolts(const Value& v);

// case_monitors.cpp: monitors.
std::vector<MonitorSpec> read_monitors(const Value& v);

}  // namespace bimrock::case_file
