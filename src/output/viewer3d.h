// The interactive 3D view of the HTML reports: drape.glb files (src/output/gltf.h) shown in a
// WebGL canvas with three.js (Debian's libjs-three, read at run time and embedded in the page, so
// the page stands alone and works offline): drag to orbit, scroll to zoom, right-drag to pan; the
// fabric coloured by a field chosen in a list (its height, displacement, area stretch, contact
// force); the obstacles, the shadow and the fold crests as the file holds them; a list of shapes
// where the block has several (a lab's fabrics, a run's drops).
//
// Where three.js is not found the page says so in the view's place ("3D view not drawn: …") and
// links the files: never a silently missing view.
#ifndef DRAPE_SRC_OUTPUT_VIEWER3D_H_
#define DRAPE_SRC_OUTPUT_VIEWER3D_H_

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace drape {

// One shape of a view: its name in the list and its drape.glb, relative to the report's folder.
struct ViewerShape {
  std::string label;
  std::string file;
};

// The folder of three.js's files: $DRAPE_THREE_JS_DIR where set, else Debian's
// /usr/share/javascript/three.
std::filesystem::path ThreeJsFolder();

// The scripts every view of a page needs (three.js, its glTF loader and orbit controls, and
// drape's viewer), as one <script> element; empty with `*missing` saying why where a file of
// three.js cannot be read.
std::string ViewerScripts(std::string* missing);

// At most this many shapes are embedded in one view (the first ones; a 5 mm drape's drape.glb is
// about 0.3 MB, a third more in base64): a table of a hundred fabrics or a sweep of a thousand
// tasks keeps a page a browser opens; the view says how many it holds of how many.
constexpr size_t kViewerMaxShapes = 24;

// A view's HTML: a canvas, the lists, and the shapes embedded (base64); `index` tells the page's
// views apart. The shapes that cannot be read are left out (none left: a paragraph saying so).
std::string ViewerHtml(const std::vector<ViewerShape>& shapes, const std::filesystem::path& folder,
                       int index);

}  // namespace drape

#endif  // DRAPE_SRC_OUTPUT_VIEWER3D_H_
