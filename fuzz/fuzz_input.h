// How the fuzz target (fuzz/scene_fuzzer.cc) turns bytes into a scene and mesh files and runs the
// scene loader and the model builder on them. An input is a scene; if it holds the line
// "---mesh---", what follows that line is also written as the mesh files mesh.obj, mesh.ply and
// mesh.stl next to the scene (a scene reaches them with `mesh: {kind: file, path: mesh.obj}`,
// `mesh.ply` or `mesh.stl`: text or binary PLY and STL; the seeds fuzz/corpus/mesh_*). A scene must
// load (or be refused with an InputError), and a loaded scene must build into a model whose
// positions and masses are finite (or be refused with an InputError). Anything else — a crash, a
// hang, a sanitizer report, another exception — is a bug.
#ifndef DRAPE_FUZZ_FUZZ_INPUT_H_
#define DRAPE_FUZZ_FUZZ_INPUT_H_

#include <cstddef>
#include <cstdint>
#include <string>

namespace drape_fuzz {

// The number of nodes of the model built from the input; -1 if the scene or the model was refused
// (InputError); -2 if the scene loaded but its mesh is too large to build here. Aborts on a model
// with a non-finite position or mass.
int RunInput(const uint8_t* data, size_t size);

// The folder RunInput writes into: drape_fuzz_<pid> under $TMPDIR (else /tmp), made on the
// process's first call, removed when that process ends normally (a crash leaves it, with the
// input that crashed).
std::string InputFolder();

}  // namespace drape_fuzz

#endif  // DRAPE_FUZZ_FUZZ_INPUT_H_
