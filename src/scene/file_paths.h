// Paths written in an input file, taken relative to that file's folder: one rule for scene files,
// fit files and sweep files.
#ifndef DRAPE_SRC_SCENE_FILE_PATHS_H_
#define DRAPE_SRC_SCENE_FILE_PATHS_H_

#include <string>

namespace drape {

// `path` against `directory`, normalised: "a" + "../b/x" → "b/x"; an absolute path stays as given
// (normalised).
std::string ResolvePath(const std::string& directory, const std::string& path);

// The folder of a file's path, "." for a bare file name.
std::string DirectoryOf(const std::string& path);

// Where the results of the input file named `name` in `directory` go unless it or the command
// line says otherwise: out/<name> beside it (scene, fit and sweep files alike).
std::string DefaultResultFolder(const std::string& directory, const std::string& name);

}  // namespace drape

#endif  // DRAPE_SRC_SCENE_FILE_PATHS_H_
