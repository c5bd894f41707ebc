// The case-file reader: the document (one YAML document, `schema: 1` first), then one small
// function per section (case_sections.hpp), each knowing its keys (from the one table kKeys,
// case_keys.cpp), defaults, units and syntax checks. Everything that needs the whole model
// (convexity, overlaps, material names, positive stiffness) is left to build_model().
#include <bimrock/io/case_reader.hpp>

#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <system_error>
#include <vector>

#include <bimrock/io/case_sections.hpp>
#include <bimrock/io/gmsh_mesh.hpp>
#include <bimrock/io/yaml_value.hpp>

namespace bimrock::case_file {
namespace {

constexpr int kSchemaVersion = 1;

/// `schema: 1` must come first, so that a file that is not a case file (or a later schema) is
/// recognised before anything else is said about it.
void check_schema(const Value& root) {
  const std::vector<Entry> entries = root.entries();
  if (entries.empty())
    root.fail("the case file is empty: it must start with 'schema: 1'");
  const Entry& first = entries.front();
  if (first.key != "schema") {
    for (const Entry& e : entries) {
      if (e.key == "schema")
        e.value.fail("must be the first key of the file");
    }
    throw InputError(std::string(root.file()), first.value.line(), "schema",
                     "missing: a case file starts with 'schema: 1' (found '" + first.key + "')");
  }
  const int version = first.value.integer();
  if (version != kSchemaVersion) {
    first.value.fail("unsupported version " + std::to_string(version) +
                     ": this bimrock reads schema " + std::to_string(kSchemaVersion));
  }
}

/// The whole document. Sections are read in dependency order (analysis before the joint
/// materials that need its plane mode); missing required sections are reported last, so that an
/// error inside a section that is there (with its line) comes first.
Case read_document(const YAML::Node& doc, const std::string& file) {
  if (!doc.IsMap()) {
    throw InputError(file, doc.Mark().is_null() ? 0 : doc.Mark().line + 1, "",
                     "a case file is a map of sections (schema, materials, blocks, ...)");
  }
  const Value root(doc, file, 0, "");
  check_schema(root);
  const Map m(root, keys_of(""));

  Case c;
  CaseSpec& s = c.spec;
  s.file = file;
  s.title = m.text_or("title", "");
  if (const auto v = m.find("analysis")) {
    s.settings = read_analysis(*v);
    c.plastic = read_plastic_options(*v);
  }
  if (const auto v = m.find("materials")) {
    s.block_materials = read_named(*v, read_block_material);
    if (s.block_materials.empty())
      v->fail("give at least one material");
  }
  if (const auto v = m.find("joint_materials")) {
    s.joint_materials =
        read_named(*v, [&](const Entry& e) { return read_joint_material(e, s.settings); });
  }
  if (const auto v = m.find("blocks")) {
    s.blocks = read_list(*v, read_block);
    if (s.blocks.empty())
      v->fail("give at least one block");
  }
  if (const auto v = m.find("domain")) {
    if (m.has("blocks"))
      v->fail("give either blocks or a domain to cut them from, not both");
    s.domain = read_domain(*v);
  }
  std::optional<GmshMesh> mesh;
  if (const auto v = m.find("mesh")) {
    if (m.has("blocks") || m.has("domain"))
      v->fail("give one of blocks, a domain or a mesh, not several");
    s.mesh = read_mesh(*v, mesh.emplace());
  }
  if (const auto v = m.find("joints"))
    read_joints(*v, s);
  if (const auto v = m.find("supports"))
    s.supports = read_list(*v, read_support);
  if (const auto v = m.find("loads"))
    s.loads = read_loads(*v);
  if (const auto v = m.find("monitors"))
    s.monitors = read_monitors(*v);
  if (const auto v = m.find("output"))
    c.output = read_output(*v);
  if (const auto v = m.find("limits"))
    s.limits = read_limits(*v);
  if (const auto v = m.find("stages")) {
    if (const auto loads = m.find("loads"))
      loads->fail("give loads either here (an elastic analysis) or in stages, not both");
    s.stages = read_stages(*v);
    if (s.stages.empty())
      v->fail("give at least one stage");
  }
  if (const auto v = m.find("initial_stress")) {
    if (!m.has("stages"))
      v->fail(
          "is the stress in the rock before the first stage: give stages (an elastic "
          "analysis, with loads, starts unstressed)");
    s.initial_stress = read_initial_stress(*v);
  }
  if (const auto v = m.find("bolts")) {
    if (!m.has("stages"))
      v->fail(
          "are installed at the start of a stage: give stages (an elastic analysis, with "
          "loads, has no bolts)");
    s.bolts = read_bolts(*v);
  }
  if (const auto v = m.find("factor_of_safety")) {
    if (!m.has("stages"))
      v->fail("a factor of safety is sought after the stages of a nonlinear analysis: give stages");
    c.plastic.factor_of_safety = read_factor_of_safety(*v, s);
  }
  resolve_groups(s, mesh ? &*mesh : nullptr);
  require_keys(m, "");
  if (!m.has("blocks") && !m.has("domain") && !m.has("mesh"))
    throw InputError(file, 0, "blocks",
                     "required key 'blocks' is missing (or give a domain to cut the blocks from, "
                     "or a mesh)");
  return c;
}

/// The 1-based line of the first line that is neither blank nor a comment (0: none).
int first_content_line(const std::string& text) {
  std::istringstream in(text);
  std::string l;
  for (int line = 1; std::getline(in, l); ++line) {
    const std::size_t first = l.find_first_not_of(" \t\r");
    if (first != std::string::npos && l[first] != '#')
      return line;
  }
  return 0;
}

/// The 1-based line where a second YAML document starts (0: there is one document at most): its
/// first content after a `---` marker that follows content or an end marker `...` (the marker's
/// line if nothing follows), or content after `...`. Document
/// markers are only markers at the start of a line, outside any scalar, so a line scan finds
/// them exactly.
int second_document_line(const std::string& text) {
  const auto marker = [](const std::string& l, const char* m) {
    return l.rfind(m, 0) == 0 && (l.size() == 3 || l[3] == ' ' || l[3] == '\t' || l[3] == '\r');
  };
  const auto has_content = [](const std::string& l, std::size_t from) {
    const std::size_t first = l.find_first_not_of(" \t\r", from);
    return first != std::string::npos && l[first] != '#';
  };
  std::istringstream in(text);
  std::string l;
  bool content = false;  // the first document has begun
  bool ended = false;    // ... and an end marker `...` closed it
  int second = 0;        // the line of a second `---`: the second document's content follows
  for (int line = 1; std::getline(in, l); ++line) {
    if (marker(l, "---")) {
      if (content || ended) {
        if (has_content(l, 3))
          return line;
        second = second > 0 ? second : line;
      }
      content = true;
    } else if (marker(l, "...")) {
      ended = content;
    } else if (has_content(l, 0)) {
      if (ended || second > 0)
        return line;    // the line of the second document's first content, as yaml-cpp marks it
      if (l[0] != '%')  // a directive (%YAML 1.2) before the document is not content
        content = true;
    }
  }
  return second;
}

/// Parses the text; a syntax error becomes an InputError at the line yaml-cpp reports.
/// Not YAML::LoadAll: in yaml-cpp 0.7 it loops without end, allocating, on some malformed input
/// (a file holding only `,`). Load reads the first document only; a second one is found by
/// second_document_line() and refused.
YAML::Node parse(const std::string& text, const std::string& file) {
  if (const int line = second_document_line(text)) {
    throw InputError(file, line, "", "more than one YAML document ('---'): give one case per file");
  }
  YAML::Node document;
  try {
    document = YAML::Load(text);
  } catch (const YAML::Exception& e) {
    throw InputError(file, e.mark.is_null() ? 0 : e.mark.line + 1, "", "malformed YAML: " + e.msg);
  }
  if (!document.IsDefined() || document.IsNull()) {
    if (const int line = first_content_line(text)) {
      throw InputError(file, line, "",
                       "malformed YAML: no value could be read from this line (a case file is a "
                       "map of sections, starting with 'schema: 1')");
    }
    throw InputError(file, 0, "", "the case file is empty: it must start with 'schema: 1'");
  }
  return document;
}

}  // namespace
}  // namespace bimrock::case_file

namespace bimrock {

Case read_case_string(const std::string& text, const std::string& name) {
  return case_file::read_document(case_file::parse(text, name), name);
}

Case read_case_file(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec))
    throw InputError(path, 0, "", "cannot open the case file: no such file");
  if (std::filesystem::is_directory(path, ec))
    throw InputError(path, 0, "", "cannot open the case file: it is a folder");
  std::ifstream in(path, std::ios::binary);
  if (!in)
    throw InputError(path, 0, "", "cannot open the case file (is it readable?)");
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad())
    throw InputError(path, 0, "", "cannot read the case file");
  return read_case_string(text.str(), path);
}

}  // namespace bimrock
