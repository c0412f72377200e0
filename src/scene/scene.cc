#include "src/scene/scene.h"

namespace drape {

namespace {
std::string Locate(const Location& where, const std::string& what) {
  // A place without a line (a fabric table that cannot be read, a mesh given as arrays) is its
  // file's name alone.
  std::string text = where.line > 0 ? where.file + ":" + std::to_string(where.line) + ":" +
                                          std::to_string(where.column) + ": "
                                    : where.file + ": ";
  if (!where.key.empty()) text += where.key + ": ";
  return text + what;
}
}  // namespace

InputError::InputError(const Location& where, const std::string& what)
    : std::runtime_error(Locate(where, what)), where_(where), problem_(what) {}

}  // namespace drape
