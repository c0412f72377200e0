// The drape coefficient: the area of the vertical projection (the "shadow") of a draped surface,
// taken as the union of its projected triangles (folds that overlap count once), over a flat area.
// The shadow is rasterised with cairo onto an A8 image and its covered pixels counted. Also the
// shadow's radial profile r(θ) around the disc centre and the number of folds counted on it.
#ifndef DRAPE_SRC_ANALYSIS_DRAPE_ANALYSIS_H_
#define DRAPE_SRC_ANALYSIS_DRAPE_ANALYSIS_H_

#include <array>
#include <vector>

#include "src/model/model.h"
#include "src/scene/scene.h"

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

// The specimen's surface as its shadow sees it: the model's triangles and its fringe (the strip
// between a circle mesh's staircase outline and the circle, src/model/mesh.h), at `positions`
// (3 doubles per node). Every shadow, flat area and radial profile below is taken of this surface.
struct SpecimenSurface {
  std::vector<double> points;                 // 3 per point: the nodes, then the fringe's points
  std::vector<std::array<int, 3>> triangles;  // ids into `points`
};
SpecimenSurface SurfaceAt(const Model& model, const std::vector<double>& positions);

struct DrapeCoefficient {
  Shadow shadow;         // of the final (draped) shape
  double flat_area = 0;  // m², the same union at the model's initial positions (πR² on a circle)
  double ratio = 0;      // A_shadow / A_flat (Rusinko & Swan's DC, §5)
  // Cusick's (A_shadow − A_disc) / (A_specimen − A_disc) with A_disc = π r², when a support disc
  // radius is given (> 0); NaN otherwise.
  double cusick = 0;
};

// Cusick's drape coefficient (A_shadow − A_disc) / (A_specimen − A_disc), A_disc = π r², from the
// shadow and flat (specimen) areas, m², and the support disc radius r > 0, m. A specimen no larger
// than the disc (A_specimen ≤ A_disc) cannot hang: 1, the stiff limit (no 0/0).
double CusickCoefficient(double shadow_area, double flat_area, double disc_radius);

// The radius of the scene's disk obstacle (the drape tester's support), 0 if it has none.
double DiscRadius(const Scene& scene);

// Whether the scene's result has a drape coefficient: a surface with a support disk, or a
// disc-shaped specimen (circle or arc mesh: Rusinko & Swan's disc over a pin).
bool HasDrapeCoefficient(const Scene& scene, const Model& model);

// DC of `model` at its current positions; `disc_radius` (m) ≤ 0 when there is no support disc.
DrapeCoefficient ComputeDrapeCoefficient(const Model& model, double disc_radius = 0.0,
                                         const ShadowOptions& options = {});

// The radial profile r(θ) of the shadow's outline around a centre c (top view, θ counter-clockwise
// from +x): r(θ) = the largest t ≥ 0 with c + t (cos θ, sin θ) inside the union of the projected
// triangles, i.e. the outer boundary along each ray (folds that overlap, or a fold hiding a hole
// behind it, do not shorten it). Computed exactly (up to rounding) by intersecting each ray with
// the projected edges of every triangle that casts a shadow (non-zero projected area, as in
// ProjectedArea): the farthest point of a union along a ray is the farthest point of one of its
// triangles, which lies on that triangle's boundary. The only approximation is the sampling in θ:
// `angles` equally spaced rays, θ_k = 360° k / angles, so a lobe narrower than 360°/angles can be
// missed. r = 0 where the ray meets no triangle.
struct RadialProfile {
  std::array<double, 2> centre{0.0, 0.0};  // m, (x, y)
  std::vector<double> theta;               // rad, θ_k = 2π k / angles
  std::vector<double> radius;              // m
};
RadialProfile ComputeRadialProfile(const std::vector<double>& positions,
                                   const std::vector<std::array<int, 3>>& triangles,
                                   const std::array<double, 2>& centre, int angles = 360);

// Fold counting on a sampled periodic profile v(θ_k), k = 0..N−1 (equally spaced). AnalyseDrape
// applies it to the overhang fraction (see DrapeAnalysis), any periodic profile will do.
// 1. Smoothing: circular convolution with a Gaussian of standard deviation `smoothing_deg`
//    (truncated at ±4σ). It removes the facets of the mesh outline (boundary nodes every 3–6° on
//    the meshes used: their bumps are attenuated by exp(−(2πσ/λ)²/2) < 1% for a period λ ≤ 6°)
//    and keeps folds: a fold pattern cos(nθ) keeps exp(−(nσ)²/2) of its amplitude, 82% for
//    n = 12, 58% for n = 20.
// 2. A fold is a local maximum of the smoothed profile whose prominence (its height above the
//    higher of the two lowest points met walking left and right from it before reaching a higher
//    point, as for mountain peaks; the highest peak's is its height above the global minimum) is at
//    least `relative_prominence` × (max − min of the smoothed profile) and at least
//    `absolute_prominence` × `length_scale` (or × the profile's mean if length_scale is 0). The
//    relative rule (10%) drops the ripples that mesh noise leaves after smoothing while keeping the
//    minor folds of an irregular drape (a fold a third as high as its neighbours counts); the
//    absolute rule (1%) makes a circle or an almost undraped specimen count 0 folds however its
//    small noise is shaped. Measured on configs/fv/drape_tester_cotton_30.yaml (1 cm mesh, session
//    24): its 11 folds stand 14–100% of the range above their troughs, no other maximum is left
//    after smoothing, and the count stays 11 for σ from 1.5° to 4° at thresholds of 5% and 10%;
//    at 15–20% or σ = 5° it falls to 10–6 (the weakest folds go first: a drape's folds are
//    unequal, hence the low threshold).
struct FoldOptions {
  double smoothing_deg = 3.0;
  double relative_prominence = 0.10;
  double absolute_prominence = 0.01;
  double length_scale = 0.0;  // the unit of the absolute rule; 0: the profile's mean
};

struct Folds {
  int count = 0;
  std::vector<double> angles_deg;  // θ of each fold's crest on the smoothed profile, [0, 360)
  std::vector<double> smoothed;    // the smoothed profile (same sampling as the input)
};
Folds CountFolds(const std::vector<double>& profile, const FoldOptions& options = {});

// The centre of the profile: the support disk's centre if there is one, else a pin's position,
// else the centroid of the specimen's flat shape (the triangles at the initial positions).
std::array<double, 2> ProfileCentre(const Scene& scene, const Model& model);

// Everything drape-related that the writers report for a scene with a drape coefficient.
// The folds are counted on the overhang fraction f(θ) = (r(θ) − R_d)/(r_flat(θ) − R_d): the part
// of the specimen's overhang beyond the disc (radius R_d; 0 without a disk) that still shows in
// the shadow on that ray (1 where r_flat ≤ R_d). Dividing by the flat overhang takes out the
// outline of the cut specimen where it is not round (an arc's polygon; a lattice's staircase,
// whose radius varies by up to one spacing, when a model has no fringe: 8 false "folds" at 1 cm
// on a 30 cm specimen if counted on r(θ) itself); an undraped specimen has f ≡ 1 and no folds. The
// absolute rule is 1% of the flat overhang (length_scale 1). Limit: a specimen collapsed far inside
// its outline (a disc over a pin without bending stiffness) no longer follows the cut outline, and
// the division imprints it.
struct DrapeAnalysis {
  double disc_radius = 0.0;  // m, 0 without a support disk
  DrapeCoefficient coefficient;
  RadialProfile profile;         // of the draped shape
  RadialProfile flat_profile;    // of the specimen at its initial positions (its outline)
  std::vector<double> overhang;  // f(θ), same sampling as the profiles
  Folds folds;                   // of `overhang`
  double radius_min = 0.0, radius_mean = 0.0, radius_max = 0.0;  // of profile.radius, m
};
DrapeAnalysis AnalyseDrape(const Scene& scene, const Model& model);

}  // namespace drape

#endif  // DRAPE_SRC_ANALYSIS_DRAPE_ANALYSIS_H_
