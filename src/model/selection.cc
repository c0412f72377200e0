// Node selections. Edge and corner selectors need a full rectangular lattice (a grid, a chain —
// a single row whose left/right edges are its first/last node — or a circle mesh so small that
// its lattice is full); ij, row (j) and column (i) selectors need lattice indices (grid, chain,
// circle); ids, box, within, outside and all work on every mesh. Box and within include points on
// their boundary, to 1e-9 × the mesh size.
#include "src/model/selection.h"

#include <algorithm>
#include <cassert>
#include <map>
#include <sstream>
#include <string>

namespace drape {

namespace {

bool IsFullLattice(const Mesh& mesh) {
  if (mesh.nu <= 0 || mesh.nv <= 0) return false;
  if (mesh.nodes.size() != static_cast<size_t>(mesh.nu) * mesh.nv) return false;
  for (size_t k = 0; k < mesh.grid_index.size(); ++k) {
    const auto [i, j] = mesh.grid_index[k];
    if (static_cast<size_t>(j) * mesh.nu + i != k) return false;
  }
  return mesh.grid_index.size() == mesh.nodes.size();
}

bool HasLatticeIndices(const Mesh& mesh) {
  return mesh.nu > 0 && mesh.nv > 0 && !mesh.grid_index.empty() && mesh.grid_index[0][0] >= 0;
}

double MeshSize(const Mesh& mesh) {
  Eigen::Vector3d low = mesh.nodes[0], high = mesh.nodes[0];
  for (const auto& p : mesh.nodes) {
    low = low.cwiseMin(p);
    high = high.cwiseMax(p);
  }
  return (high - low).norm();
}

// Whether lattice index (i, j) lies on the named edge ("left", "right", "bottom", "top").
bool OnEdge(const std::string& edge, int i, int j, const Mesh& mesh) {
  if (edge == "left") return i == 0;
  if (edge == "right") return i == mesh.nu - 1;
  if (edge == "bottom") return j == 0;
  if (edge == "top") return j == mesh.nv - 1;
  return false;
}

bool IsEdgeName(const std::string& name) {
  return name == "left" || name == "right" || name == "bottom" || name == "top";
}

std::vector<int> SelectEdge(const NodeSelector& selector, const Mesh& mesh) {
  if (!IsEdgeName(selector.name)) {
    throw InputError(selector.where,
                     "unknown edge '" + selector.name + "' (use left, right, bottom or top)");
  }
  std::vector<int> ids;
  for (size_t k = 0; k < mesh.nodes.size(); ++k) {
    const auto [i, j] = mesh.grid_index[k];
    if (OnEdge(selector.name, i, j, mesh)) ids.push_back(static_cast<int>(k));
  }
  return ids;
}

// A corner is two edges joined by '-', in either order: "top-left" or "left-top".
std::vector<int> SelectCorner(const NodeSelector& selector, const Mesh& mesh) {
  const auto dash = selector.name.find('-');
  const std::string first = selector.name.substr(0, dash);
  const std::string second = dash == std::string::npos ? "" : selector.name.substr(dash + 1);
  const bool vertical = first == "top" || first == "bottom";
  const bool crossing =
      vertical ? (second == "left" || second == "right")
               : ((first == "left" || first == "right") && (second == "top" || second == "bottom"));
  if (!crossing) {
    throw InputError(selector.where,
                     "unknown corner '" + selector.name +
                         "' (use bottom-left, bottom-right, top-left or top-right)");
  }
  std::vector<int> ids;
  for (size_t k = 0; k < mesh.nodes.size(); ++k) {
    const auto [i, j] = mesh.grid_index[k];
    if (OnEdge(first, i, j, mesh) && OnEdge(second, i, j, mesh)) ids.push_back(static_cast<int>(k));
  }
  return ids;
}

std::vector<int> SelectIds(const NodeSelector& selector, const Mesh& mesh) {
  const int n = static_cast<int>(mesh.nodes.size());
  for (int id : selector.ids) {
    if (id < 0 || id >= n) {
      throw InputError(selector.where, "node id " + std::to_string(id) +
                                           " is out of range (the mesh has " + std::to_string(n) +
                                           " nodes, ids 0 to " + std::to_string(n - 1) + ")");
    }
  }
  return selector.ids;
}

std::vector<int> SelectIj(const NodeSelector& selector, const Mesh& mesh) {
  if (!HasLatticeIndices(mesh)) {
    throw InputError(selector.where, "ij selectors need a grid mesh (grid, chain or circle)");
  }
  std::map<std::array<int, 2>, int> by_index;
  for (size_t k = 0; k < mesh.grid_index.size(); ++k) by_index[mesh.grid_index[k]] = k;
  std::vector<int> ids;
  for (const auto& ij : selector.ij) {
    const auto found = by_index.find(ij);
    if (found == by_index.end()) {
      std::ostringstream what;
      what << "no node has (i, j) = (" << ij[0] << ", " << ij[1] << ")";
      if (IsFullLattice(mesh)) {
        what << ": out of range (i from 0 to " << mesh.nu - 1 << ", j from 0 to " << mesh.nv - 1
             << ")";
      } else {
        what << " (outside the disc)";
      }
      throw InputError(selector.where, what.str());
    }
    ids.push_back(found->second);
  }
  return ids;
}

// row: j = index, column: i = index, on a mesh with lattice indices.
std::vector<int> SelectLine(const NodeSelector& selector, const Mesh& mesh) {
  const bool row = selector.kind == NodeSelector::Kind::kRow;
  const char* const name = row ? "row" : "column";
  if (!HasLatticeIndices(mesh)) {
    throw InputError(selector.where,
                     std::string(name) + " selectors need a grid mesh (grid, chain or circle)");
  }
  const int count = row ? mesh.nv : mesh.nu;
  if (selector.index >= count) {
    throw InputError(selector.where, std::string(name) + " " + std::to_string(selector.index) +
                                         " is out of range (" + (row ? "j" : "i") + " from 0 to " +
                                         std::to_string(count - 1) + ")");
  }
  std::vector<int> ids;
  for (size_t k = 0; k < mesh.grid_index.size(); ++k) {
    if (mesh.grid_index[k][row ? 1 : 0] == selector.index) ids.push_back(static_cast<int>(k));
  }
  return ids;
}

std::vector<int> SelectBox(const NodeSelector& selector, const Mesh& mesh) {
  const double tolerance = 1e-9 * MeshSize(mesh);
  const Eigen::Vector3d low = selector.min.array() - tolerance;
  const Eigen::Vector3d high = selector.max.array() + tolerance;
  std::vector<int> ids;
  for (size_t k = 0; k < mesh.nodes.size(); ++k) {
    const auto& p = mesh.nodes[k];
    if ((p.array() >= low.array()).all() && (p.array() <= high.array()).all()) {
      ids.push_back(static_cast<int>(k));
    }
  }
  return ids;
}

// within: distance to the centre at most the radius; outside: at least the radius (both with
// the boundary's tolerance).
std::vector<int> SelectWithin(const NodeSelector& selector, const Mesh& mesh) {
  const double tolerance = 1e-9 * MeshSize(mesh);
  const bool within = selector.kind == NodeSelector::Kind::kWithin;
  std::vector<int> ids;
  for (size_t k = 0; k < mesh.nodes.size(); ++k) {
    const double distance = (mesh.nodes[k] - selector.center).norm();
    if (within ? distance <= selector.radius + tolerance
               : distance >= selector.radius - tolerance) {
      ids.push_back(static_cast<int>(k));
    }
  }
  return ids;
}

}  // namespace

std::vector<int> SelectNodes(const NodeSelector& selector, const Mesh& mesh) {
  assert(selector.region.empty() && "the loader resolves {region: name} selections");
  std::vector<int> ids;
  switch (selector.kind) {
    case NodeSelector::Kind::kEdge:
    case NodeSelector::Kind::kCorner:
      if (!IsFullLattice(mesh)) {
        throw InputError(selector.where,
                         "edge selectors need a grid mesh (or a chain); select by ids, box or "
                         "within instead");
      }
      ids = selector.kind == NodeSelector::Kind::kEdge ? SelectEdge(selector, mesh)
                                                       : SelectCorner(selector, mesh);
      break;
    case NodeSelector::Kind::kIds:
      ids = SelectIds(selector, mesh);
      break;
    case NodeSelector::Kind::kIj:
      ids = SelectIj(selector, mesh);
      break;
    case NodeSelector::Kind::kBox:
      ids = SelectBox(selector, mesh);
      break;
    case NodeSelector::Kind::kRow:
    case NodeSelector::Kind::kColumn:
      ids = SelectLine(selector, mesh);
      break;
    case NodeSelector::Kind::kWithin:
    case NodeSelector::Kind::kOutside:
      ids = SelectWithin(selector, mesh);
      break;
    case NodeSelector::Kind::kAll:
      ids.resize(mesh.nodes.size());
      for (size_t k = 0; k < ids.size(); ++k) ids[k] = static_cast<int>(k);
      break;
  }
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  if (ids.empty()) throw InputError(selector.where, "the selection selects no node");
  return ids;
}

}  // namespace drape
