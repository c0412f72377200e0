// The output kinds (see output_kinds.h).
#include "src/scene/output_kinds.h"

#include "src/scene/registry_row.h"

namespace drape {

const std::vector<OutputKindRow>& OutputKinds() {
  static const std::vector<OutputKindRow> kinds = {
      {OutputKind::kSummary, "summary", {"summary.json"}, "the run's figures", true, false},
      {OutputKind::kNodes, "nodes", {"nodes.csv"}, "one row per node", true, false},
      {OutputKind::kHistory,
       "history",
       {"history.csv", "kinetic_<method>.csv"},
       "one row per iteration; and the per-step trace of a method that records one",
       true,
       false},
      {OutputKind::kVtk, "vtk", {"mesh.vtk"}, "the final mesh for ParaView", true, false},
      {OutputKind::kObj, "obj", {"mesh.obj"}, "the final mesh for Blender", true, false},
      {OutputKind::kGltf,
       "gltf",
       {"drape.glb"},
       "the final shape in 3D as binary glTF 2.0, for Blender, three.js or any glTF viewer: the "
       "fabric with its normals, flat pattern, a colour by height and per-vertex fields, and the "
       "obstacles",
       false,
       true},
      {OutputKind::kPng,
       "png",
       {"drape.png", "shadow.png"},
       "the pictures (`shadow.png` only with a drape coefficient)",
       false,
       false},
      {OutputKind::kKinetic,
       "kinetic",
       {"kinetic_<method>.csv"},
       "the per-step trace alone, for the methods that record one",
       false,
       false},
      {OutputKind::kProfile,
       "profile",
       {"profile.csv"},
       "the shadow's radial profile, only with a drape coefficient",
       false,
       true},
      {OutputKind::kShadow,
       "shadow",
       {"shadow.png"},
       "the shadow's picture alone, only with a drape coefficient",
       false,
       true},
  };
  return kinds;
}

const OutputKindRow& OutputKindOf(OutputKind kind) {
  return RegistryRow(OutputKinds(), &OutputKindRow::kind, kind);
}

const OutputKindRow* FindOutputKind(const std::string& name) {
  for (const OutputKindRow& row : OutputKinds()) {
    if (row.name == name) return &row;
  }
  return nullptr;
}

std::vector<std::string> OutputKindNames() {
  std::vector<std::string> names;
  for (const OutputKindRow& row : OutputKinds()) names.push_back(row.name);
  return names;
}

std::vector<std::string> DefaultOutputWrite(bool drape_test) {
  std::vector<std::string> names;
  for (const OutputKindRow& row : OutputKinds()) {
    if (row.by_default || (drape_test && row.for_drape_test)) names.push_back(row.name);
  }
  return names;
}

std::string OutputFileName(const std::string& pattern, const std::string& solver) {
  const std::string placeholder = kMethodPlaceholder;
  const size_t at = pattern.find(placeholder);
  if (at == std::string::npos) return pattern;
  return pattern.substr(0, at) + solver + pattern.substr(at + placeholder.size());
}

std::string TraceFileName(const std::string& solver) {
  return OutputFileName(OutputKindOf(OutputKind::kKinetic).files.front(), solver);
}

}  // namespace drape
