// The lookup shared by the registries whose rows are keyed by an enum value (the output kinds,
// the material models): each value has exactly one row, which their tests check.
#ifndef DRAPE_SRC_SCENE_REGISTRY_ROW_H_
#define DRAPE_SRC_SCENE_REGISTRY_ROW_H_

#include <cassert>
#include <vector>

namespace drape {

// The row of `rows` whose `field` is `key`.
template <typename Row, typename Key>
const Row& RegistryRow(const std::vector<Row>& rows, Key Row::*field, Key key) {
  for (const Row& row : rows) {
    if (row.*field == key) return row;
  }
  assert(false && "an enum value without its row in the registry");
  return rows.front();
}

}  // namespace drape

#endif  // DRAPE_SRC_SCENE_REGISTRY_ROW_H_
