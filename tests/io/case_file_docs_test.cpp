// docs/case-file.md and the reader agree: every key the reader accepts has a row in the docs,
// every row names a key the reader accepts, and every complete example in the docs reads, builds
// into a model and solves.
#include <gtest/gtest.h>

#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <bimrock/analysis/elastic_analysis.hpp>
#include <bimrock/io/case_reader.hpp>
#include <bimrock/model/model.hpp>

namespace bimrock {
namespace {

std::vector<std::string> doc_lines() {
  std::ifstream in(std::string(BIMROCK_SOURCE_DIR) + "/docs/case-file.md");
  EXPECT_TRUE(in) << "docs/case-file.md not found";
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);)
    lines.push_back(line);
  return lines;
}

/// The key of each table row: the first `...` of lines starting with "| `".
std::set<std::string> documented_keys() {
  std::set<std::string> keys;
  for (const std::string& line : doc_lines()) {
    if (line.rfind("| `", 0) != 0)
      continue;
    const std::size_t end = line.find('`', 3);
    if (end != std::string::npos)
      keys.insert(line.substr(3, end - 3));
  }
  return keys;
}

/// The ```yaml blocks that are whole case files (start with "schema:"), with their first line.
std::vector<std::pair<int, std::string>> example_cases() {
  std::vector<std::pair<int, std::string>> cases;
  const std::vector<std::string> lines = doc_lines();
  for (std::size_t k = 0; k < lines.size(); ++k) {
    if (lines[k] != "```yaml")
      continue;
    std::string text;
    std::size_t j = k + 1;
    for (; j < lines.size() && lines[j] != "```"; ++j)
      text += lines[j] + "\n";
    if (text.rfind("schema:", 0) == 0)
      cases.emplace_back(static_cast<int>(k + 2), text);
    k = j;
  }
  return cases;
}

TEST(CaseFileDocs, DocumentEveryKeyTheReaderAccepts) {
  const std::set<std::string> documented = documented_keys();
  for (const CaseKey& key : case_file_keys())
    EXPECT_TRUE(documented.count(key.path())) << "no table row for `" << key.path() << "`";
}

TEST(CaseFileDocs, DocumentNoKeyTheReaderRejects) {
  std::set<std::string> accepted;
  for (const CaseKey& key : case_file_keys())
    accepted.insert(key.path());
  for (const std::string& key : documented_keys())
    EXPECT_TRUE(accepted.count(key)) << "docs describe `" << key << "`, which the reader rejects";
}

TEST(CaseFileDocs, KeyTableHasNoDuplicates) {
  std::set<std::string> seen;
  for (const CaseKey& key : case_file_keys())
    EXPECT_TRUE(seen.insert(key.path()).second) << key.path() << " listed twice";
}

TEST(CaseFileDocs, CompleteExamplesReadBuildAndSolve) {
  const std::vector<std::pair<int, std::string>> cases = example_cases();
  ASSERT_FALSE(cases.empty()) << "docs/case-file.md has no complete example";
  for (const auto& [line, text] : cases) {
    SCOPED_TRACE("example starting on line " + std::to_string(line) + " of docs/case-file.md");
    try {
      const Case c = read_case_string(text, "docs/case-file.md example");
      const Model m = build_model(c.spec);
      EXPECT_GT(m.n_blocks(), 0);
      static_cast<void>(solve_elastic(m));  // supported: no block can move freely
    } catch (const std::exception& e) {
      ADD_FAILURE() << e.what();
    }
  }
}

}  // namespace
}  // namespace bimrock
