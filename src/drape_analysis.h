// The drape coefficient: the area of the vertical projection (the "shadow") of a draped surface,
// taken as the union of its projected triangles (folds that overlap count once), over a flat area.
// The shadow is rasterised with cairo onto an A8 image and its covered pixels counted.
#ifndef DRAPE_SRC_DRAPE_ANALYSIS_H_
#define DRAPE_SRC_DRAPE_ANALYSIS_H_

#include <array>
#include <vector>

#include "src/model.h"
#include "src/scene.h"

namespace drape {

struct ShadowOptions {
  // Pixel size = (extent of the projection) / resolution. The area's error is about
  // perimeter × pixel size / 2 (half a pixel along the outline, where coverage is fractional
  // cairo antialiasing is used and counted as a fraction, which reduces it further).
  int resolution = 2048;
};

struct Shadow {
  double area = 0.0;         // m², union of the projected triangles
  double pixel_size = 0.0;   // m
  double error_bound = 0.0;  // m², perimeter of the union × pixel size / 2 (estimated)
};

// Union area of the triangles `triangles` (node ids into `positions`, 3 doubles per node)
// projected onto the x-y plane.
Shadow ProjectedArea(const std::vector<double>& positions,
                     const std::vector<std::array<int, 3>>& triangles,
                     const ShadowOptions& options = {});

struct DrapeCoefficient {
  Shadow shadow;         // of the final (draped) shape
  double flat_area = 0;  // m², the same union at the model's initial positions
  double ratio = 0;      // A_shadow / A_flat (Rusinko & Swan's DC, §5)
  // Cusick's (A_shadow − A_disc) / (A_specimen − A_disc) with A_disc = π r², when a support disc
  // radius is given (> 0); NaN otherwise.
  double cusick = 0;
};

// The radius of the scene's disk obstacle (the drape tester's support), 0 if it has none.
double DiscRadius(const Scene& scene);

// Whether the scene's result has a drape coefficient: a surface with a support disk, or a
// disc-shaped specimen (circle or arc mesh: Rusinko & Swan's disc over a pin).
bool HasDrapeCoefficient(const Scene& scene, const Model& model);

// DC of `model` at its current positions; `disc_radius` (m) ≤ 0 when there is no support disc.
DrapeCoefficient ComputeDrapeCoefficient(const Model& model, double disc_radius = 0.0,
                                         const ShadowOptions& options = {});

}  // namespace drape

#endif  // DRAPE_SRC_DRAPE_ANALYSIS_H_
