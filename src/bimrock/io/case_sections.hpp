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

}  // namespace bimrock::case_file
