// The scene's `drape_test` block: a drape test (Cusick 1968; BS 5058, ISO 9073-9) given by its
// geometry, so that a scene says the fabric and the test and nothing else. It expands into what a
// hand-written tester scene says (configs/fv/ has both forms):
//   mesh       circle of radius specimen_diameter/2, spacing mesh.spacing (default: what the
//              test's accuracy needs, ChooseDrapeTestSpacing), lying
//              on the disc's clearance layer (z = contact.thickness);
//   fixed      the nodes within clamp_diameter/2 of the disc's centre (x, y and z): the specimen
//              clamped between the support and cover discs;
//   obstacles  the support disc, radius disc_diameter/2, centred at `offset` (x, y) at z = 0;
//   loads      gravity (0, 0, −9.81) m/s² unless the scene gives its own.
// The ring between the clamp and the disc's rim rests on the disc by contact, over which the
// fabric folds.
#ifndef DRAPE_SRC_SCENE_DRAPE_TESTER_H_
#define DRAPE_SRC_SCENE_DRAPE_TESTER_H_

#include <string>
#include <vector>

#include "src/scene/scene.h"
#include "src/scene/yaml_reader.h"

namespace drape {

// The most drops one run solves (drape_test.drops, `drape solve --drops`, Python's drape.drops).
constexpr int kMostDrops = 10000;

// The keys of the block, in the order the documentation lists them.
const std::vector<std::string>& DrapeTestKeys();

// The mesh keys a scene with a drape_test may still give (the rest is the test's).
const std::vector<std::string>& DrapeTestMeshKeys();

// Reads and checks the block (lengths positive, the clamp inside the disc, the disc inside the
// specimen); throws InputError, located.
DrapeTestSpec ReadDrapeTest(const YamlValue& value);

// Fills the scene's mesh (keeping its spacing and max_nodes), fixed, obstacles and gravity from
// scene->drape_test, which must be set; contact.thickness must be read already.
void ExpandDrapeTest(Scene* scene);

// Where the scene gives no mesh.spacing: the spacing the mesh rule says reaches the test's
// accuracy (drape_test.accuracy, else kDefaultDrapeAccuracy; src/scene/drape_mesh_rule.h), no
// coarser than kCoarsestChosenSpacing, and drape_test.spacing_chosen. A fabric the rule does not
// cover keeps the mesh's default (and may not give an accuracy: RequireTheMeshRuleForAnAccuracy).
// Throws InputError, located at the accuracy, where that lattice would exceed mesh.max_nodes. The
// material, the loads and the mesh must be read already.
void ChooseDrapeTestSpacing(Scene* scene);

// Throws InputError, located at drape_test.accuracy, where the scene gives an accuracy that the
// mesh rule cannot hold it to: a fabric the rule does not cover (springs, a mass not given per
// unit area, no bending rigidity or gravity), whose accuracy would otherwise go unused.
void RequireTheMeshRuleForAnAccuracy(const Scene& scene);

// The block and what it expands to, for `drape check`: two lines.
std::string DrapeTestText(const Scene& scene);

// The clamp's diameter in effect (given, else 1 cm less than the disc), m.
double ClampDiameter(const DrapeTestSpec& test);

}  // namespace drape

#endif  // DRAPE_SRC_SCENE_DRAPE_TESTER_H_
