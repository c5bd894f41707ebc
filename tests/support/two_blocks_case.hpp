#pragma once
// A valid elastic case as YAML text: two 1 m blocks side by side on a fixed base (SI units).
// The header ends with `blocks:` on line 9, so block 0 is on line 10 and block 1 on line 11.
#include <string>

namespace bimrock::testing {

inline const std::string kTwoBlocksHeader = R"(schema: 1
materials:
  rock: {E: 10.0e9, nu: 0.2}
joint_materials:
  joint: {kn: 1.0e10, ks: 1.0e10}
joints: {default: joint}
supports:
  - {line: [[0, 0], [2, 0]], type: fixed}
blocks:
)";
inline const std::string kTwoBlocksBlock0 =
    "  - {material: rock, vertices: [[0, 0], [1, 0], [1, 1], [0, 1]]}\n";
inline const std::string kTwoBlocksBlock1 =
    "  - {material: rock, vertices: [[1, 0], [2, 0], [2, 1], [1, 1]]}\n";

}  // namespace bimrock::testing
