// drape.glb: the final shape in 3D as binary glTF 2.0 (Khronos Group, "glTF 2.0 Specification",
// 2021), written with Debian's tinygltf, for Blender, three.js and any glTF viewer.
//
// What it holds, in glTF's axes (+Y up, metres, right-handed: drape's (x, y, z) is written
// (x, z, −y), the turn that mesh.obj's `obj_up: y` makes):
// - the node "fabric": its triangles (the surface's winding: the normals point to the face that was
//   up on the flat sheet) with POSITION, NORMAL (area-weighted, src/output/surface_fields.h),
//   TEXCOORD_0 (the flat pattern) and COLOR_0 (the height, from blue at the lowest point to sand at
//   the highest), and the per-vertex fields as application attributes (underscore names, float):
//   kGltfFields below; a chain's links as LINES with POSITION and the fields;
// - one node per obstacle surface part ("obstacle 1", …), its polygons as drape.png draws them
//   (src/output/render.h's ObstaclePolygons), grey, two-sided;
// - with a drape (SolveReport::drape): the node "shadow", its outline r(θ) about the profile's
//   centre as a flat fan a hundredth of the fabric's extent below its lowest point, and the node
//   "fold crests", a red line at each crest's angle from the support disk's rim (or the centre) to
//   the outline, on the shadow;
// - extras: on the scene its name, drape's provenance line and each field's unit.
// No animation: a solve records no frames of its path.
#ifndef DRAPE_SRC_OUTPUT_GLTF_H_
#define DRAPE_SRC_OUTPUT_GLTF_H_

#include <ostream>
#include <string>
#include <vector>

#include "src/model/model.h"
#include "src/output/provenance.h"
#include "src/run/solve_report.h"
#include "src/scene/scene.h"

namespace drape {

// A per-vertex field of drape.glb: its attribute name, its unit and its meaning.
struct GltfField {
  std::string attribute;  // "_HEIGHT"
  std::string unit;       // "m"
  std::string meaning;
};
// _HEIGHT, _DISPLACEMENT, _AREA_STRETCH, _CONTACT_FORCE, _FIXED, in the file's order.
const std::vector<GltfField>& GltfFields();

// Writes drape.glb of `model` at its current positions (the fabric must have a node).
void WriteGlb(const Scene& scene, const Model& model, const SolveReport& report,
              const Provenance& provenance, std::ostream& out);

}  // namespace drape

#endif  // DRAPE_SRC_OUTPUT_GLTF_H_
