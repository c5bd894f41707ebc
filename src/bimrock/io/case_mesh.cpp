/// @file The mesh section: the cells of a gmsh mesh as blocks, their physical surfaces mapped to
/// materials, and the physical curves that group selectors name.
#include <bimrock/io/case_sections.hpp>

#include <algorithm>
#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <system_error>
#include <vector>

namespace bimrock::case_file {

namespace {

std::string quoted_list(const std::vector<std::string>& names) {
  std::string out;
  for (const std::string& n : names)
    out += (out.empty() ? "'" : ", '") + n + "'";
  return out.empty() ? "none" : out;
}

std::string cell_item(const MeshCell& c) {
  return "element " + std::to_string(c.tag) + " (surface " + std::to_string(c.surface) + ")";
}

/// The material of each cell: the one its physical surface is mapped to in mesh.materials.
/// Every physical surface with cells must be mapped, every key must be a physical surface.
void map_materials(const Value& materials, const GmshMesh& mesh, MeshSpec& spec) {
  for (const MeshCell& c : mesh.cells) {
    if (c.groups.empty()) {
      const std::string surface = std::to_string(c.surface);
      throw InputError(mesh.file, c.line, cell_item(c),
                       "belongs to no physical surface, so it has no material: in gmsh, put "
                       "surface " +
                           surface + " in a physical group (`Physical Surface(\"rock\") = {" +
                           surface + "};`) and map the group in mesh.materials");
    }
  }
  const std::vector<std::string> surfaces = mesh.group_names(2);
  std::map<std::string, std::string> material_of;
  for (const Entry& e : materials.entries()) {
    if (!std::binary_search(surfaces.begin(), surfaces.end(), e.key)) {
      e.value.fail("'" + e.key + "' is not a physical surface of " + mesh.file +
                   " (its physical surfaces: " + quoted_list(surfaces) + ")");
    }
    material_of[e.key] = name(e.value);
    spec.materials.push_back({e.key, material_of[e.key], e.value.ref()});
  }
  std::set<std::string> unmapped;
  for (const MeshCell& c : mesh.cells) {
    for (const std::string& g : c.groups) {
      if (!material_of.count(g))
        unmapped.insert(g);
    }
  }
  if (!unmapped.empty()) {
    materials.fail("no material for physical surface" +
                   std::string(unmapped.size() > 1 ? "s " : " ") +
                   quoted_list({unmapped.begin(), unmapped.end()}) + " of " + mesh.file +
                   ": map each to a block material, e.g. {" + *unmapped.begin() + ": <material>}");
  }
  for (const MeshCell& c : mesh.cells) {
    std::string material;
    for (const std::string& g : c.groups) {
      const std::string& m = material_of.at(g);
      if (!material.empty() && m != material) {
        throw InputError(mesh.file, c.line, cell_item(c),
                         "lies in physical surfaces " + quoted_list(c.groups) +
                             " mapped to different materials: give each cell one material");
      }
      material = m;
    }
    spec.cells.push_back(
        {c.polygon,
         material,
         {0, "mesh " + cell_item(c) + " (" + mesh.file + ":" + std::to_string(c.line) + ")"}});
  }
}

}  // namespace

/// mesh: {file, materials, interfaces}: the cells of a gmsh mesh as blocks (io/gmsh_mesh.hpp).
/// The mesh file is relative to the case file's folder.
MeshSpec read_mesh(const Value& v, GmshMesh& mesh) {
  const Map m = open(v, "mesh");
  MeshSpec spec;
  spec.source = v.ref();
  const Value file = m.at("file");
  std::filesystem::path path(name(file));
  if (path.is_relative())
    path = std::filesystem::path(std::string(v.file())).parent_path() / path;
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) {
    file.fail("cannot open the mesh file " + path.string() + ": " +
              (std::filesystem::exists(path, ec) ? "not a file" : "no such file") +
              " (a relative path is taken from the case file's folder)");
  }
  mesh = read_gmsh_mesh(path.string());
  spec.file = mesh.file;
  if (mesh.cells.empty())
    file.fail(mesh.file + " has no triangles or quadrangles (was it meshed in 2D, `gmsh -2`?)");
  const Value materials = m.at("materials");
  if (materials.entries().empty())
    materials.fail("map at least one physical surface to a block material");
  map_materials(materials, mesh, spec);
  if (const auto i = m.find("interfaces")) {
    spec.interfaces = name(*i);
    if (spec.interfaces == "continuum")
      spec.interfaces.clear();
  }
  return spec;
}

/// Fills the segments of every group selector from the line elements of the mesh's physical
/// curve of that name. A group that is not a physical curve is named with the ones there are.
void resolve_groups(CaseSpec& s, const GmshMesh* mesh) {
  const auto resolve = [&](Selector& sel) {
    if (sel.kind != Selector::Kind::group)
      return;
    if (!mesh) {
      throw InputError(s.file, sel.source,
                       "a group selects the line elements of a mesh's physical curve: give a "
                       "mesh section, or select by line or box");
    }
    for (const MeshLine& l : mesh->lines) {
      if (std::find(l.groups.begin(), l.groups.end(), sel.group) != l.groups.end())
        sel.segments.push_back(l.segment);
    }
    if (!sel.segments.empty())
      return;
    const std::vector<std::string> curves = mesh->group_names(1);
    const std::vector<std::string> surfaces = mesh->group_names(2);
    std::string why = "unknown group '" + sel.group + "': not a physical curve of " + mesh->file;
    if (std::binary_search(curves.begin(), curves.end(), sel.group))
      why = "physical curve '" + sel.group + "' of " + mesh->file + " has no line elements";
    else if (std::binary_search(surfaces.begin(), surfaces.end(), sel.group))
      why = "'" + sel.group + "' is a physical surface of " + mesh->file +
            "; select edges by a physical curve";
    throw InputError(s.file, sel.source,
                     why + " (its physical curves: " + quoted_list(curves) + ")");
  };
  for (JointRule& r : s.joint_rules)
    resolve(r.where);
  for (SupportSpec& sup : s.supports)
    resolve(sup.where);
  for (TractionSpec& t : s.loads.tractions)
    resolve(t.where);
  for (StageSpec& st : s.stages) {
    for (TractionSpec& t : st.loads.tractions)
      resolve(t.where);
  }
}

}  // namespace bimrock::case_file
