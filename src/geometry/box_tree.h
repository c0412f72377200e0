// A bounding-box tree over items (triangles): the broad phase of the self-intersection check
// (src/model/self_intersection.h) and of a mesh obstacle's nearest-point query
// (src/geometry/triangle_surface.h).
//
// Each tree node holds the box around its items; a leaf holds at most kLeafSize. Built by
// splitting the items at the median of their boxes' centres along the longest side of the
// centres' box: O(n log n), depth O(log n).
#ifndef DRAPE_SRC_GEOMETRY_BOX_TREE_H_
#define DRAPE_SRC_GEOMETRY_BOX_TREE_H_

#include <Eigen/Core>
#include <algorithm>
#include <limits>
#include <utility>
#include <vector>

namespace drape {

struct Box {
  Eigen::Vector3d low = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector3d high = Eigen::Vector3d::Constant(-std::numeric_limits<double>::infinity());
  void Add(const Eigen::Vector3d& point) {
    low = low.cwiseMin(point);
    high = high.cwiseMax(point);
  }
  void Add(const Box& box) {
    low = low.cwiseMin(box.low);
    high = high.cwiseMax(box.high);
  }
  bool Overlaps(const Box& box) const {
    return (low.array() <= box.high.array()).all() && (box.low.array() <= high.array()).all();
  }
  Eigen::Vector3d Centre() const { return 0.5 * (low + high); }
  // The squared distance from `point` to the box (0 inside it).
  double SquaredDistance(const Eigen::Vector3d& point) const {
    const Eigen::Vector3d outside =
        (low - point).cwiseMax(point - high).cwiseMax(Eigen::Vector3d::Zero());
    return outside.squaredNorm();
  }
};

class BoxTree {
 public:
  explicit BoxTree(std::vector<Box> boxes) : boxes_(std::move(boxes)), order_(boxes_.size()) {
    for (int i = 0; i < static_cast<int>(order_.size()); ++i) order_[i] = i;
    if (!order_.empty()) Build(0, static_cast<int>(order_.size()));
  }

  bool empty() const { return nodes_.empty(); }
  const Box& bounds() const { return nodes_.front().box; }

  // Calls visit(item) for every item whose box overlaps `query`.
  template <typename Visit>
  void ForEachOverlap(const Box& query, Visit visit) const {
    if (nodes_.empty()) return;
    std::vector<int> stack = {0};
    while (!stack.empty()) {
      const Node& node = nodes_[stack.back()];
      stack.pop_back();
      if (!node.box.Overlaps(query)) continue;
      if (node.left < 0) {
        for (int k = node.first; k < node.first + node.count; ++k) {
          if (boxes_[order_[k]].Overlaps(query)) visit(order_[k]);
        }
      } else {
        stack.push_back(node.left);
        stack.push_back(node.right);
      }
    }
  }

  // Branch and bound for the item nearest `point`: squared_distance(item) gives an item's squared
  // distance to the point (at least its box's). Items farther than √bound are not looked at.
  // Returns the nearest item and sets *best to its squared distance; -1 (and *best = bound) when
  // no item is nearer than √bound.
  template <typename SquaredDistance>
  int Nearest(const Eigen::Vector3d& point, double bound, SquaredDistance squared_distance,
              double* best) const {
    *best = bound;
    int nearest = -1;
    if (nodes_.empty()) return nearest;
    // (node, its box's squared distance), nearer child popped first; a node's children replace it
    // on the stack, so it holds at most one node per level and one more (depth ≤ 2 log₂ n).
    std::pair<int, double> stack[kMaxDepth + 1];
    int size = 0;
    stack[size++] = {0, nodes_[0].box.SquaredDistance(point)};
    while (size > 0) {
      const auto [index, box_distance] = stack[--size];
      if (box_distance >= *best) continue;
      const Node& node = nodes_[index];
      if (node.left < 0) {
        for (int k = node.first; k < node.first + node.count; ++k) {
          const int item = order_[k];
          if (boxes_[item].SquaredDistance(point) >= *best) continue;
          const double distance = squared_distance(item);
          if (distance < *best) *best = distance, nearest = item;
        }
        continue;
      }
      const double left = nodes_[node.left].box.SquaredDistance(point);
      const double right = nodes_[node.right].box.SquaredDistance(point);
      if (left <= right) {
        stack[size++] = {node.right, right};
        stack[size++] = {node.left, left};
      } else {
        stack[size++] = {node.left, left};
        stack[size++] = {node.right, right};
      }
    }
    return nearest;
  }

 private:
  static constexpr int kLeafSize = 4;
  // The median split halves the items at each level: 64 levels hold any vector's size.
  static constexpr int kMaxDepth = 128;
  struct Node {
    Box box;
    int first = 0, count = 0;
    int left = -1, right = -1;  // its children's indices; -1 for a leaf
  };

  // The node of order_[first, first + count): returns its index.
  int Build(int first, int count) {
    const int index = static_cast<int>(nodes_.size());
    nodes_.emplace_back();
    Box box, centres;
    for (int k = first; k < first + count; ++k) {
      box.Add(boxes_[order_[k]]);
      centres.Add(boxes_[order_[k]].Centre());
    }
    nodes_[index].box = box;
    nodes_[index].first = first;
    nodes_[index].count = count;
    if (count <= kLeafSize) return index;
    int axis = 0;
    (centres.high - centres.low).maxCoeff(&axis);
    const int half = count / 2;
    std::nth_element(
        order_.begin() + first, order_.begin() + first + half, order_.begin() + first + count,
        [&](int a, int b) { return boxes_[a].Centre()[axis] < boxes_[b].Centre()[axis]; });
    const int left = Build(first, half);
    const int right = Build(first + half, count - half);
    nodes_[index].left = left;
    nodes_[index].right = right;
    return index;
  }

  std::vector<Box> boxes_;
  std::vector<int> order_;
  std::vector<Node> nodes_;
};

}  // namespace drape

#endif  // DRAPE_SRC_GEOMETRY_BOX_TREE_H_
