#include "src/model/selection.h"

#include <gtest/gtest.h>

#include <string>

namespace drape {
namespace {

constexpr int kNu = 4, kNv = 3;

Mesh Grid() {
  MeshSpec spec;
  spec.nodes = {kNu, kNv};
  spec.size = {0.3, 0.2};  // spacing 0.1 both ways
  return BuildMesh(spec);
}

int Id(int i, int j) { return j * kNu + i; }

NodeSelector Selector(NodeSelector::Kind kind, const std::string& name = "") {
  NodeSelector selector;
  selector.kind = kind;
  selector.name = name;
  selector.where = Location{"scene.yaml", 7, 12, "fixed[0].nodes"};
  return selector;
}

std::string ErrorOf(const NodeSelector& selector, const Mesh& mesh) {
  try {
    SelectNodes(selector, mesh);
  } catch (const InputError& error) {
    return error.what();
  }
  return "";
}

TEST(Selection, EdgesOfAGrid) {
  const Mesh mesh = Grid();
  std::vector<int> left, right, bottom, top;
  for (int j = 0; j < kNv; ++j) left.push_back(Id(0, j));
  for (int j = 0; j < kNv; ++j) right.push_back(Id(kNu - 1, j));
  for (int i = 0; i < kNu; ++i) bottom.push_back(Id(i, 0));
  for (int i = 0; i < kNu; ++i) top.push_back(Id(i, kNv - 1));
  EXPECT_EQ(SelectNodes(Selector(NodeSelector::Kind::kEdge, "left"), mesh), left);
  EXPECT_EQ(SelectNodes(Selector(NodeSelector::Kind::kEdge, "right"), mesh), right);
  EXPECT_EQ(SelectNodes(Selector(NodeSelector::Kind::kEdge, "bottom"), mesh), bottom);
  EXPECT_EQ(SelectNodes(Selector(NodeSelector::Kind::kEdge, "top"), mesh), top);
}

TEST(Selection, CornersOfAGrid) {
  const Mesh mesh = Grid();
  using V = std::vector<int>;
  EXPECT_EQ(SelectNodes(Selector(NodeSelector::Kind::kCorner, "bottom-left"), mesh), V{Id(0, 0)});
  EXPECT_EQ(SelectNodes(Selector(NodeSelector::Kind::kCorner, "bottom-right"), mesh),
            V{Id(kNu - 1, 0)});
  EXPECT_EQ(SelectNodes(Selector(NodeSelector::Kind::kCorner, "top-left"), mesh),
            V{Id(0, kNv - 1)});
  EXPECT_EQ(SelectNodes(Selector(NodeSelector::Kind::kCorner, "top-right"), mesh),
            V{Id(kNu - 1, kNv - 1)});
  EXPECT_NE(ErrorOf(Selector(NodeSelector::Kind::kCorner, "top-bottom"), mesh).find("unknown"),
            std::string::npos);
}

TEST(Selection, IdsAreSortedWithoutRepeatsAndRangeChecked) {
  const Mesh mesh = Grid();
  NodeSelector selector = Selector(NodeSelector::Kind::kIds);
  selector.ids = {5, 2, 5};
  EXPECT_EQ(SelectNodes(selector, mesh), (std::vector<int>{2, 5}));
  selector.ids = {1, kNu * kNv};
  const std::string message = ErrorOf(selector, mesh);
  EXPECT_EQ(message.rfind("scene.yaml:7:12: fixed[0].nodes: ", 0), 0u) << message;
  EXPECT_NE(message.find("node id " + std::to_string(kNu * kNv) + " is out of range"),
            std::string::npos)
      << message;
  selector.ids = {-1};
  EXPECT_NE(ErrorOf(selector, mesh).find("node id -1"), std::string::npos);
}

TEST(Selection, IjPicksGridNodesAndRangeChecks) {
  const Mesh mesh = Grid();
  NodeSelector selector = Selector(NodeSelector::Kind::kIj);
  selector.ij = {{1, 2}, {3, 0}};
  EXPECT_EQ(SelectNodes(selector, mesh), (std::vector<int>{Id(3, 0), Id(1, 2)}));
  selector.ij = {{kNu, 0}};
  const std::string message = ErrorOf(selector, mesh);
  EXPECT_NE(message.find("out of range"), std::string::npos) << message;
  EXPECT_NE(message.find("(" + std::to_string(kNu) + ", 0)"), std::string::npos) << message;
}

TEST(Selection, BoxIsInclusive) {
  const Mesh mesh = Grid();
  NodeSelector selector = Selector(NodeSelector::Kind::kBox);
  // Exactly the nodes with x in [0.1, 0.2] and y in [0, 0.1]: boundaries included.
  selector.min = {0.1, 0.0, -1.0};
  selector.max = {0.2, 0.1, 1.0};
  EXPECT_EQ(SelectNodes(selector, mesh),
            (std::vector<int>{Id(1, 0), Id(2, 0), Id(1, 1), Id(2, 1)}));
}

TEST(Selection, WithinADistance) {
  const Mesh mesh = Grid();
  NodeSelector selector = Selector(NodeSelector::Kind::kWithin);
  selector.center = mesh.nodes[Id(1, 1)];
  selector.radius = 0.1;  // the node and its four lattice neighbours, not the diagonals
  EXPECT_EQ(SelectNodes(selector, mesh),
            (std::vector<int>{Id(1, 0), Id(0, 1), Id(1, 1), Id(2, 1), Id(1, 2)}));
}

TEST(Selection, RowsColumnsAndOutside) {
  const Mesh mesh = Grid();
  NodeSelector row = Selector(NodeSelector::Kind::kRow);
  row.index = 1;
  EXPECT_EQ(SelectNodes(row, mesh), (std::vector<int>{Id(0, 1), Id(1, 1), Id(2, 1), Id(3, 1)}));
  NodeSelector column = Selector(NodeSelector::Kind::kColumn);
  column.index = 3;
  EXPECT_EQ(SelectNodes(column, mesh), (std::vector<int>{Id(3, 0), Id(3, 1), Id(3, 2)}));
  column.index = 4;
  EXPECT_EQ(ErrorOf(column, mesh),
            "scene.yaml:7:12: fixed[0].nodes: column 4 is out of range (i from 0 to 3)");
  NodeSelector outside = Selector(NodeSelector::Kind::kOutside);
  outside.center = mesh.nodes[Id(1, 1)];
  outside.radius = 0.2;  // on the boundary (distance 0.2) counts; the diagonal at 0.1414 not
  EXPECT_EQ(SelectNodes(outside, mesh), (std::vector<int>{Id(3, 0), Id(3, 1), Id(3, 2)}));
}

TEST(Selection, AllNodes) {
  const Mesh mesh = Grid();
  EXPECT_EQ(SelectNodes(Selector(NodeSelector::Kind::kAll), mesh).size(), mesh.nodes.size());
}

TEST(Selection, EmptySelectionIsAnError) {
  const Mesh mesh = Grid();
  NodeSelector selector = Selector(NodeSelector::Kind::kBox);
  selector.min = {5.0, 5.0, 5.0};
  selector.max = {6.0, 6.0, 6.0};
  const std::string message = ErrorOf(selector, mesh);
  EXPECT_EQ(message.rfind("scene.yaml:7:12: fixed[0].nodes: ", 0), 0u) << message;
  EXPECT_NE(message.find("selects no node"), std::string::npos) << message;
}

TEST(Selection, EdgeOfANonGridIsAnError) {
  MeshSpec spec;
  spec.kind = MeshSpec::Kind::kArc;
  spec.rings = 2;
  spec.spokes = 6;
  const Mesh arc = BuildMesh(spec);
  const std::string message = ErrorOf(Selector(NodeSelector::Kind::kEdge, "left"), arc);
  EXPECT_NE(message.find("edge selectors need a grid mesh"), std::string::npos) << message;
  NodeSelector ij = Selector(NodeSelector::Kind::kIj);
  ij.ij = {{0, 0}};
  EXPECT_NE(ErrorOf(ij, arc).find("need a grid mesh"), std::string::npos);
}

TEST(Selection, ChainEndsAreItsLeftAndRightEdges) {
  MeshSpec spec;
  spec.kind = MeshSpec::Kind::kChain;
  spec.chain_nodes = 7;
  const Mesh chain = BuildMesh(spec);
  EXPECT_EQ(SelectNodes(Selector(NodeSelector::Kind::kEdge, "left"), chain), std::vector<int>{0});
  EXPECT_EQ(SelectNodes(Selector(NodeSelector::Kind::kEdge, "right"), chain),
            std::vector<int>{spec.chain_nodes - 1});
}

TEST(Selection, IjOnACircleFindsLatticePoints) {
  MeshSpec spec;
  spec.kind = MeshSpec::Kind::kCircle;
  spec.radius = 0.03;
  spec.spacing = 0.01;  // lattice i, j in [0, 6], centre (3, 3)
  const Mesh circle = BuildMesh(spec);
  NodeSelector selector = Selector(NodeSelector::Kind::kIj);
  selector.ij = {{3, 3}};
  const std::vector<int> centre = SelectNodes(selector, circle);
  ASSERT_EQ(centre.size(), 1u);
  EXPECT_NEAR(circle.nodes[centre[0]].norm(), 0.0, 1e-15);
  selector.ij = {{0, 0}};  // a corner of the bounding square, outside the disc
  EXPECT_NE(ErrorOf(selector, circle).find("outside the disc"), std::string::npos);
  EXPECT_NE(ErrorOf(Selector(NodeSelector::Kind::kEdge, "top"), circle).find("grid mesh"),
            std::string::npos);
}

}  // namespace
}  // namespace drape
