// Pictures of a result, drawn with cairo (vector drawing, antialiased, written as PNG):
// - drape.png: a shaded 3-D view of the final shape (every mesh kind) with the obstacles;
// - shadow.png: the top view of a drape (flat specimen outline, disc, shadow, folds, DC).
#ifndef DRAPE_SRC_OUTPUT_RENDER_H_
#define DRAPE_SRC_OUTPUT_RENDER_H_

#include <array>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "src/analysis/drape_analysis.h"
#include "src/model/model.h"
#include "src/scene/scene.h"

namespace drape {

// The 3-D view: an orthographic camera looking down at the scene from the direction given by an
// azimuth (from +x towards +y, degrees) and an elevation (above the x-y plane, degrees); 2-D
// scenes (dimension 2, x-z plane) are seen from the front (from −y, elevation 0). Triangles
// (fabric and obstacles) are painted back to front (painter's algorithm: sorted by the depth of
// their centroid; obstacles' polygons are pushed back by two fabric edge lengths plus their
// own size, so that a disc or sphere touching the fabric from below is not painted over it), shaded
// with Lambert's law I = 0.35 + 0.65 |n·l| (two-sided) for a fixed light l from the upper left of
// the viewer. The fabric's two faces have two colours: blue the face whose normal (by the mesh's
// triangle winding: +z on the flat starting sheet) points to the viewer, sand the other, so that
// the inside of a fold or the underside of a skirt shows; mesh edges are drawn as thin lines when
// they are at least 8 pixels long. Line elements (chains) are polylines; fully fixed nodes are
// black squares, partly fixed ones hollow squares (beyond 40 fixed nodes, small dots). The vertical
// projection of the fabric is drawn in grey on a floor (3-D views): 5% of the fabric's extent
// below its lowest point, or on a horizontal plane obstacle under it; none when a box, cylinder or
// sphere reaches lower. A scale bar gives lengths in the picture plane.
struct DrapeViewOptions;

// What drape.png draws, and in which style: the one table its painting and its legend read, so
// that the legend cannot name a colour the picture does not use.
enum class DrawnKind { kUpperFace, kLowerFace, kChain, kFixedNode, kPartlyFixedNode, kObstacle };
enum class LegendMark { kSwatch, kLine, kFilledSquare, kHollowSquare };
struct Rgb {
  double r, g, b;
};
struct DrawnStyle {
  DrawnKind kind;
  std::string label;  // the legend's words
  Rgb colour;
  LegendMark mark;  // how the legend shows it
};
const std::vector<DrawnStyle>& DrawnStyles();  // one row per DrawnKind, in legend order
const DrawnStyle& StyleOf(DrawnKind kind);

// drape.png's legend for `scene` and `model`: the kinds the picture draws, once each, in table
// order (the fabric's faces for a surface, the chain for line elements, fully and partly fixed
// nodes where there are any, the obstacles where there are any).
std::vector<DrawnKind> DrapeLegend(const Scene& scene, const Model& model);

// A pixel (column, row) that the legend's entry `index` paints wholly in its colour, in a
// picture `width` pixels wide (the legend is top right, one entry per 18-pixel row).
std::array<int, 2> LegendMarkPixel(int index, LegendMark mark, int width);

struct DrapeViewOptions {
  int width = 900, height = 700;  // pixels
  double azimuth_deg = -60.0, elevation_deg = 30.0;
  std::vector<std::string> caption;  // extra lines under the title (e.g. the drape coefficient)
};

// Writes the 3-D view of `model` at its current positions (with the scene's obstacles) as a PNG.
// Throws std::runtime_error if cairo fails.
void DrawDrapeView(const Scene& scene, const Model& model, std::ostream& png,
                   const DrapeViewOptions& options = {});

// The obstacles' surfaces as drape.png draws them (src/model/obstacle_kinds.h's parts: spheres,
// cylinders and boxes as facets, a plane as a patch around the fabric at its current positions,
// a disk as a flat cylinder), each a planar polygon whose corners go round it in order, m.
std::vector<std::vector<Eigen::Vector3d>> ObstaclePolygons(const Scene& scene, const Model& model);

// The top view of a drape (x to the right, y up, seen from above): the specimen's flat outline
// (dashed), the support disc (filled grey; without one, the fixed nodes as a pin), the shadow
// (the union of the projected triangles, translucent blue) with its outline r(θ), the fold crests
// (red dots), light circles every round radius around the centre, a scale bar in cm, and as text
// the drape coefficient in both conventions (Cusick's with its error bar where given), the fold
// count and the radii.
struct ShadowViewOptions {
  int size = 800;  // pixels, square
  // Cusick's drape coefficient's error bar (the stdout line's), drawn beside it where given.
  std::optional<double> drape_coefficient_error;
};

// A drape coefficient as text: three decimals ("0.710"), or two significant digits below 0.001.
std::string CoefficientText(double value);

void DrawShadowView(const Scene& scene, const Model& model, const DrapeAnalysis& analysis,
                    std::ostream& png, const ShadowViewOptions& options = {});

}  // namespace drape

#endif  // DRAPE_SRC_OUTPUT_RENDER_H_
