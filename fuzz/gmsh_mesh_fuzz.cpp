// libFuzzer target: the gmsh reader, MSH text -> cells, lines and groups (io/gmsh_mesh.hpp).
// Every input must end in a mesh whose cells are valid blocks or in one InputError naming the
// file; a crash, any other exception, a hang or unbounded memory is a finding.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include <bimrock/io/gmsh_mesh.hpp>
#include <bimrock/model/errors.hpp>

#include "fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const bimrock::GmshMesh mesh = bimrock::parse_gmsh_mesh(text, "fuzz.msh");
    // The reader promises blocks: every cell it returns passes the model's own check.
    for (const bimrock::MeshCell& c : mesh.cells) {
      const bimrock::PolygonCheck check = bimrock::check_convex_polygon(c.polygon, 0.0);
      if (check.defect != bimrock::PolygonDefect::none) {
        std::fprintf(stderr, "element %lld returned but %s\n", static_cast<long long>(c.tag),
                     bimrock::describe(check).c_str());
        std::abort();
      }
    }
  } catch (const bimrock::InputError& e) {
    bimrock::fuzz::expect_located(e);
  }
  return 0;
}
