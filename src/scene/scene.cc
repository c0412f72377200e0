#include "src/scene/scene.h"

namespace drape {

namespace {
std::string Locate(const Location& where, const std::string& what) {
  std::string text =
      where.file + ":" + std::to_string(where.line) + ":" + std::to_string(where.column) + ": ";
  if (!where.key.empty()) text += where.key + ": ";
  return text + what;
}
}  // namespace

InputError::InputError(const Location& where, const std::string& what)
    : std::runtime_error(Locate(where, what)), where_(where), problem_(what) {}

}  // namespace drape
