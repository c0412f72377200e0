#include "src/output/provenance.h"

#include <gtest/gtest.h>

#include <string>

#include "src/output/version.h"

namespace drape {
namespace {

TEST(ProvenanceMembers, AreVersionKernelsCommandAndOverridesInOrder) {
  const auto members = ProvenanceMembers({"drape solve 'a b.yaml'", {"mesh.nodes=5", "x=\"q\""}});
  ASSERT_EQ(members.size(), 4u);
  EXPECT_EQ(members[0].first, "drape_version");
  EXPECT_EQ(members[0].second, "\"" + DrapeVersion() + "\"");
  EXPECT_EQ(members[1].first, "blas_kernels");
  EXPECT_EQ(members[2].first, "command_line");
  EXPECT_EQ(members[2].second, "\"drape solve 'a b.yaml'\"");
  EXPECT_EQ(members[3].first, "overrides");
  EXPECT_EQ(members[3].second, "[\"mesh.nodes=5\", \"x=\\\"q\\\"\"]");
}

// The line names the version first (a VTK title keeps its first 250 characters), and the
// overrides only where the command line does not already hold them (Python's runs).
TEST(ProvenanceLine, OneLineWithTheVersionFirst) {
  EXPECT_EQ(ProvenanceLine({"drape solve s.yaml --set a=1", {"a=1"}}),
            "drape " + DrapeVersion() + "; command: drape solve s.yaml --set a=1");
  EXPECT_EQ(ProvenanceLine({"python: drape.solve", {"a=1", "b=2"}}),
            "drape " + DrapeVersion() + "; command: python: drape.solve; overrides: a=1, b=2");
  EXPECT_EQ(ProvenanceLine({"drape solve 'x\ny.yaml'", {}}).find('\n'), std::string::npos);
}

}  // namespace
}  // namespace drape
