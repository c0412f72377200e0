// A block of docs/reference.md that a registry writes (between `<!-- NAME -->` and
// `<!-- /NAME -->`): the test holds the page to the registry's text, or, with
// DRAPE_WRITE_SCHEMA_DOCS=1, writes the text into the page instead of comparing.
#ifndef DRAPE_TESTS_REFERENCE_BLOCK_H_
#define DRAPE_TESTS_REFERENCE_BLOCK_H_

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

#include "tests/test_paths.h"

namespace drape::testing {

// `what` names the registry in the failure ("FabricColumns()").
inline void ExpectReferenceBlock(const std::string& name, const std::string& text,
                                 const std::string& what) {
  const std::string path = std::string(drape_tests::kSourceDir) + "/docs/reference.md";
  std::ifstream in(path);
  std::stringstream whole;
  whole << in.rdbuf();
  std::string doc = whole.str();
  const std::string begin = "<!-- " + name + " -->\n", end = "<!-- /" + name + " -->";
  const size_t from = doc.find(begin), to = doc.find(end);
  ASSERT_NE(from, std::string::npos) << "docs/reference.md has no " << begin;
  ASSERT_NE(to, std::string::npos) << "docs/reference.md has no " << end;
  const size_t start = from + begin.size();
  if (std::getenv("DRAPE_WRITE_SCHEMA_DOCS") != nullptr) {
    doc.replace(start, to - start, text);
    std::ofstream(path) << doc;
    return;
  }
  EXPECT_EQ(doc.substr(start, to - start), text)
      << "docs/reference.md's block " << name << " is not " << what << ": regenerate it";
}

}  // namespace drape::testing

#endif  // DRAPE_TESTS_REFERENCE_BLOCK_H_
