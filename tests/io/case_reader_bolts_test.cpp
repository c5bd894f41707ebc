// The bolts section: every key read with its line, defaults, and bad keys and values refused with
// the file, the line and the item. Ranges and the stage's name are add_bolts()'s (model tests).
#include <map>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include <bimrock/io/case_reader.hpp>

#include "support/read_error.hpp"

namespace bimrock {
namespace {

using testing::read_error_of;

// Line numbers matter: 8 lines, so that `bolts:` is line 9 and its first bolt starts on line 10.
const std::string kBoltsCase = R"(schema: 1
materials:
  rock: {E: 10.0e9, nu: 0.2}
blocks:
  - {material: rock, vertices: [[0, 0], [1, 0], [1, 1], [0, 1]]}
stages:
  - name: gravity
  - name: support
)";

// kBoltsCase with `bolts:` and one bolt whose keys are `keys` (flow style, on line 10).
std::string one_bolt(const std::string& keys) {
  return kBoltsCase + "bolts:\n  - {" + keys + "}\n";
}

// The required keys of a bolt, each with a valid value.
const std::vector<std::pair<std::string, std::string>> kRequired = {
    {"kind", "anchored"},         {"from", "[0, 0]"},    {"to", "[1, 1]"},
    {"axial_stiffness", "5.0e7"}, {"capacity", "2.5e5"},
};

// The required keys, flow style, with `key` given `value` ("": left out); a key not required is
// added.
std::string required_keys_but(const std::string& key = "", const std::string& value = "") {
  std::string keys;
  bool found = false;
  for (const auto& [k, v] : kRequired) {
    found = found || k == key;
    if (k == key && value.empty())
      continue;
    keys += (keys.empty() ? "" : ", ") + k + ": " + (k == key ? value : v);
  }
  if (!found && !key.empty())
    keys += ", " + key + ": " + value;
  return keys;
}

TEST(CaseReaderBolts, ReadsEveryKeyAndItsLine) {
  const Case c = read_case_string(kBoltsCase + R"(bolts:
  - name: crown 1
    kind: anchored
    from: [0.0, 5.0]
    to: [0.0, 9.0]
    axial_stiffness: 5.0e7
    capacity: 2.5e5
    pretension: 1.0e5
    shear_stiffness: 1.0e7
    shear_capacity: 1.0e5
    spacing: 1.5
    install: support
)",
                                  "case.yaml");
  ASSERT_EQ(c.spec.bolts.size(), 1u);
  const BoltSpec& b = c.spec.bolts[0];
  EXPECT_EQ(b.name, "crown 1");
  EXPECT_EQ(b.kind, BoltSpec::Kind::anchored);
  EXPECT_EQ(b.from, Vec2(0.0, 5.0));
  EXPECT_EQ(b.to, Vec2(0.0, 9.0));
  EXPECT_EQ(b.axial_stiffness, 5.0e7);
  EXPECT_EQ(b.capacity, 2.5e5);
  EXPECT_EQ(b.pretension, 1.0e5);
  EXPECT_EQ(b.shear_stiffness, 1.0e7);
  ASSERT_TRUE(b.shear_capacity.has_value());
  EXPECT_EQ(*b.shear_capacity, 1.0e5);
  ASSERT_TRUE(b.spacing.has_value());
  EXPECT_EQ(*b.spacing, 1.5);
  EXPECT_EQ(b.install, "support");
  EXPECT_EQ(b.source.line, 10);
  EXPECT_EQ(b.source.item, "bolts[0]");
  const std::map<std::string, int> lines = {
      {"bolts[0]", 10},
      {"bolts[0].name", 10},
      {"bolts[0].kind", 11},
      {"bolts[0].from", 12},
      {"bolts[0].to", 13},
      {"bolts[0].axial_stiffness", 14},
      {"bolts[0].capacity", 15},
      {"bolts[0].pretension", 16},
      {"bolts[0].shear_stiffness", 17},
      {"bolts[0].shear_capacity", 18},
      {"bolts[0].spacing", 19},
      {"bolts[0].install", 20},
  };
  EXPECT_EQ(b.lines, lines);
}

TEST(CaseReaderBolts, OptionalKeysTakeTheirDefaults) {
  const Case c = read_case_string(one_bolt(required_keys_but("kind", "grouted")), "case.yaml");
  ASSERT_EQ(c.spec.bolts.size(), 1u);
  const BoltSpec& b = c.spec.bolts[0];
  EXPECT_EQ(b.name, "");  // "bolt 0" once built
  EXPECT_EQ(b.kind, BoltSpec::Kind::grouted);
  EXPECT_EQ(b.pretension, 0.0);
  EXPECT_EQ(b.shear_stiffness, 0.0);
  EXPECT_FALSE(b.shear_capacity.has_value());
  EXPECT_FALSE(b.spacing.has_value());
  EXPECT_EQ(b.install, "");
  EXPECT_EQ(b.lines.count("bolts[0].pretension"), 0u);
  EXPECT_EQ(b.lines.at("bolts[0].capacity"), 10);
}

TEST(CaseReaderBolts, ReadsSeveralBoltsInOrder) {
  const Case c = read_case_string(kBoltsCase + "bolts:\n  - {name: a, " + required_keys_but() +
                                      "}\n  - {name: b, " + required_keys_but() + "}\n",
                                  "case.yaml");
  ASSERT_EQ(c.spec.bolts.size(), 2u);
  EXPECT_EQ(c.spec.bolts[0].name, "a");
  EXPECT_EQ(c.spec.bolts[1].name, "b");
  EXPECT_EQ(c.spec.bolts[1].source.item, "bolts[1]");
  EXPECT_EQ(c.spec.bolts[1].lines.at("bolts[1].kind"), 11);
}

TEST(CaseReaderBolts, NoBoltsWithoutTheSection) {
  EXPECT_TRUE(read_case_string(kBoltsCase, "case.yaml").spec.bolts.empty());
}

TEST(CaseReaderBolts, RejectsEachMissingRequiredKey) {
  for (const auto& [key, value] : kRequired) {
    SCOPED_TRACE(key);
    EXPECT_EQ(read_error_of(one_bolt(required_keys_but(key))),
              "case.yaml:10: bolts[0]." + key + ": required key '" + key + "' is missing");
  }
}

TEST(CaseReaderBolts, RejectsAnUnknownKeyNamingTheAllowedOnes) {
  EXPECT_EQ(read_error_of(kBoltsCase + "bolts:\n  - kind: anchored\n    lenght: 4\n"),
            "case.yaml:11: bolts[0].lenght: unknown key 'lenght' (allowed here: name, kind, from, "
            "to, axial_stiffness, capacity, pretension, shear_stiffness, shear_capacity, spacing, "
            "install)");
}

TEST(CaseReaderBolts, RejectsARepeatedKey) {
  EXPECT_EQ(read_error_of(kBoltsCase + "bolts:\n  - kind: anchored\n    kind: grouted\n"),
            "case.yaml:11: bolts[0].kind: key given twice (first on line 10)");
}

TEST(CaseReaderBolts, RejectsValuesOfTheWrongType) {
  const struct {
    std::string keys;
    std::string error;
  } cases[] = {
      {required_keys_but("kind", "bolted"),
       "bolts[0].kind: unknown value 'bolted' (allowed: anchored, grouted)"},
      {required_keys_but("from", "5"), "bolts[0].from: must be a point [x, y]"},
      {required_keys_but("to", "[1, 2, 3]"), "bolts[0].to: must be a point [x, y]"},
      {required_keys_but("axial_stiffness", "\"5.0e7\""), "bolts[0].axial_stiffness: "},
      {required_keys_but("capacity", "250 kN"), "bolts[0].capacity: "},
      {required_keys_but("pretension", ".nan"), "bolts[0].pretension: "},
      {required_keys_but("shear_stiffness", "[1]"), "bolts[0].shear_stiffness: "},
      {required_keys_but("shear_capacity", "true"), "bolts[0].shear_capacity: "},
      {required_keys_but("spacing", "{a: 1}"), "bolts[0].spacing: "},
      {required_keys_but("install", "\"\""), "bolts[0].install: must not be empty"},
      {required_keys_but("install", "[support]"), "bolts[0].install: "},
      {required_keys_but("name", "\"\""), "bolts[0].name: must not be empty"},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.keys);
    EXPECT_EQ(read_error_of(one_bolt(c.keys)).rfind("case.yaml:10: " + c.error, 0), 0u)
        << read_error_of(one_bolt(c.keys));
  }
}

TEST(CaseReaderBolts, RejectsNumbersBeyondTheirBounds) {
  EXPECT_EQ(read_error_of(one_bolt(required_keys_but("pretension", "2.0e15"))),
            "case.yaml:10: bolts[0].pretension: must be at most 1e+15 N in magnitude (larger "
            "loads overflow the displacements)");
  EXPECT_EQ(read_error_of(one_bolt(required_keys_but("shear_stiffness", "1.0e21"))),
            "case.yaml:10: bolts[0].shear_stiffness: must be at most 1e+20 N/m in magnitude (no "
            "rock or joint is stiffer; larger values overflow)");
  EXPECT_EQ(read_error_of(one_bolt(required_keys_but("from", "[0, 2.0e9]"))),
            "case.yaml:10: bolts[0].from: coordinates must lie within +-1e+09 m, not [0, 2e+09]");
}

TEST(CaseReaderBolts, LeavesRangesToTheModel) {
  // A negative capacity has the right form: build_model refuses it (tests/model/bolts_test.cpp).
  const Case c = read_case_string(one_bolt(required_keys_but("capacity", "-1")), "case.yaml");
  EXPECT_EQ(c.spec.bolts[0].capacity, -1.0);
}

TEST(CaseReaderBolts, RejectsBoltsThatAreNotAListOfMaps) {
  EXPECT_EQ(read_error_of(kBoltsCase + "bolts: {kind: anchored}\n")
                .rfind("case.yaml:9: bolts: must be a list [...]", 0),
            0u);
  EXPECT_EQ(read_error_of(kBoltsCase + "bolts:\n  - anchored\n")
                .rfind("case.yaml:10: bolts[0]: must be a map", 0),
            0u);
}

TEST(CaseReaderBolts, RejectsBoltsWithoutStages) {
  std::string text = one_bolt(required_keys_but());
  text.replace(text.find("stages:"), text.find("bolts:") - text.find("stages:"),
               "loads: {gravity: [0, -1]}\n");
  EXPECT_EQ(read_error_of(text),
            "case.yaml:7: bolts: are installed at the start of a stage: give stages (an elastic "
            "analysis, with loads, has no bolts)");
}

}  // namespace
}  // namespace bimrock
