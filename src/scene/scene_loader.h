// Reading a scene file: YAML → Scene, with every key checked and every error located
// ("file:line:column: key.path: what is wrong"). Nothing is solved or written here.
#ifndef DRAPE_SRC_SCENE_SCENE_LOADER_H_
#define DRAPE_SRC_SCENE_SCENE_LOADER_H_

#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "src/scene/scene.h"
#include "src/scene/yaml_overrides.h"

namespace drape {

// Loads and validates `path`. `overrides` are "key.path=value" strings (`--set`), applied to the
// document before validation; a value is parsed as YAML (`--set mesh.nodes=[30,30]`).
// Throws InputError on any bad input.
Scene LoadScene(const std::string& path, const std::vector<std::string>& overrides = {});

// A scene file read once. Each Load builds a Scene from its text, with `--set` overrides and then
// typed values set on the document, validated as LoadScene does (the same errors; a value's
// located as the override after the text overrides): a fit's evaluations, a sweep's tasks and a
// fabric table's rows load their scenes without reading the file again, and their numbers are
// set as numbers, not through text. The text is parsed by each load (a syntax error is the first
// load's error, as LoadScene's), not kept parsed: yaml-cpp cannot copy a document with its marks,
// which locate every error, and assigning a node of a shared document into another re-points the
// shared document's memory (memory_holder::merge), which would grow with every load and race
// between threads.
// LoadScene(path, overrides) is Read(path).Load(overrides).
class SceneDocument {
 public:
  static SceneDocument Read(const std::string& path);
  // As LoadSceneText: errors in `label`, relative paths from `directory`, the name "scene".
  static SceneDocument Parse(const std::string& text, const std::string& label,
                             const std::string& directory);

  Scene Load(const std::vector<std::string>& overrides = {},
             const std::vector<SceneValue>& values = {}) const;

  // The file's text as read (a sweep's fingerprint of its base scene).
  const std::string& text() const { return text_; }

 private:
  Scene blank_;       // file, folder and default name
  std::string what_;  // "scene file" or "scene", for messages
  std::string text_;
  // Held while a load copies its values into its document: the values are yaml-cpp nodes that
  // loads on several threads share (a sweep's `set:` values are every task's), and reading one
  // is not safe from two threads at once.
  std::shared_ptr<std::mutex> loading_ = std::make_shared<std::mutex>();
};

// The same for a scene's YAML text (the Python module's drape.loads): errors are located in
// `label` (e.g. "<string>"), relative paths in it (mesh.path, output.directory) are taken from
// `directory`, and the scene's name, where it gives none, is "scene".
Scene LoadSceneText(const std::string& text, const std::string& label, const std::string& directory,
                    const std::vector<std::string>& overrides = {});

}  // namespace drape

#endif  // DRAPE_SRC_SCENE_SCENE_LOADER_H_
