#include "src/analysis/drape_analysis.h"

#include <cairo.h>

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <memory>

#include "src/model/obstacle_kinds.h"

namespace drape {

namespace {

struct Bounds {
  double x0 = std::numeric_limits<double>::infinity(), y0 = x0;
  double x1 = -x0, y1 = -x0;
};

Bounds ProjectedBounds(const std::vector<double>& positions,
                       const std::vector<std::array<int, 3>>& triangles) {
  Bounds b;
  for (const auto& t : triangles) {
    for (int v : t) {
      const auto p = NodeAt(positions, v);
      b.x0 = std::min(b.x0, p.x());
      b.x1 = std::max(b.x1, p.x());
      b.y0 = std::min(b.y0, p.y());
      b.y1 = std::max(b.y1, p.y());
    }
  }
  return b;
}

// Sum of the alpha values of an A8 surface, in pixels (a fully covered pixel counts 1).
double CoveredPixels(cairo_surface_t* surface) {
  cairo_surface_flush(surface);
  const unsigned char* data = cairo_image_surface_get_data(surface);
  const int width = cairo_image_surface_get_width(surface);
  const int height = cairo_image_surface_get_height(surface);
  const int stride = cairo_image_surface_get_stride(surface);
  double sum = 0.0;
  for (int row = 0; row < height; ++row) {
    for (int column = 0; column < width; ++column) sum += data[row * stride + column];
  }
  return sum / 255.0;
}

// Pixels on the outline of the union: covered pixels with an uncovered 4-neighbour, or partly
// covered ones. Times the pixel size, an estimate of the perimeter.
double OutlinePixels(cairo_surface_t* surface) {
  const unsigned char* data = cairo_image_surface_get_data(surface);
  const int width = cairo_image_surface_get_width(surface);
  const int height = cairo_image_surface_get_height(surface);
  const int stride = cairo_image_surface_get_stride(surface);
  auto at = [&](int r, int c) {
    return (r < 0 || c < 0 || r >= height || c >= width) ? 0 : data[r * stride + c];
  };
  double count = 0.0;
  for (int r = 0; r < height; ++r) {
    for (int c = 0; c < width; ++c) {
      const int a = at(r, c);
      if (a == 0) continue;
      if (a < 255 || at(r - 1, c) == 0 || at(r + 1, c) == 0 || at(r, c - 1) == 0 ||
          at(r, c + 1) == 0)
        count += 1.0;
    }
  }
  return count;
}

}  // namespace

Shadow ProjectedArea(const std::vector<double>& positions,
                     const std::vector<std::array<int, 3>>& triangles,
                     const ShadowOptions& options) {
  Shadow shadow;
  if (triangles.empty()) return shadow;
  const Bounds b = ProjectedBounds(positions, triangles);
  const double extent = std::max(b.x1 - b.x0, b.y1 - b.y0);
  if (!(extent > 0.0)) return shadow;
  const int margin = 2;
  const double pixel = extent / options.resolution;
  const int width = static_cast<int>(std::ceil((b.x1 - b.x0) / pixel)) + 2 * margin;
  const int height = static_cast<int>(std::ceil((b.y1 - b.y0) / pixel)) + 2 * margin;
  std::unique_ptr<cairo_surface_t, decltype(&cairo_surface_destroy)> surface(
      cairo_image_surface_create(CAIRO_FORMAT_A8, width, height), cairo_surface_destroy);
  std::unique_ptr<cairo_t, decltype(&cairo_destroy)> cr(cairo_create(surface.get()), cairo_destroy);
  cairo_set_antialias(cr.get(), CAIRO_ANTIALIAS_GOOD);
  cairo_set_fill_rule(cr.get(), CAIRO_FILL_RULE_WINDING);
  cairo_set_source_rgba(cr.get(), 0, 0, 0, 1);
  // Nonzero winding with every triangle wound the same way (counter-clockwise) fills their union.
  auto px = [&](int v) { return margin + (NodeAt(positions, v).x() - b.x0) / pixel; };
  auto py = [&](int v) { return margin + (NodeAt(positions, v).y() - b.y0) / pixel; };
  for (const auto& t : triangles) {
    const double cross = (px(t[1]) - px(t[0])) * (py(t[2]) - py(t[0])) -
                         (py(t[1]) - py(t[0])) * (px(t[2]) - px(t[0]));
    if (cross == 0.0) continue;  // seen edge-on: no area
    const int second = cross > 0.0 ? t[1] : t[2], third = cross > 0.0 ? t[2] : t[1];
    cairo_move_to(cr.get(), px(t[0]), py(t[0]));
    cairo_line_to(cr.get(), px(second), py(second));
    cairo_line_to(cr.get(), px(third), py(third));
    cairo_close_path(cr.get());
  }
  cairo_fill(cr.get());
  shadow.pixel_size = pixel;
  shadow.area = CoveredPixels(surface.get()) * pixel * pixel;
  shadow.error_bound = 0.5 * OutlinePixels(surface.get()) * pixel * pixel;
  return shadow;
}

double CusickCoefficient(double shadow_area, double flat_area, double disc_radius) {
  const double disc = M_PI * disc_radius * disc_radius;
  return flat_area > disc ? (shadow_area - disc) / (flat_area - disc) : 1.0;
}

SpecimenSurface SurfaceAt(const Model& model, const std::vector<double>& positions) {
  SpecimenSurface surface{WithFringePoints(model.fringe, positions), model.triangles};
  surface.triangles.insert(surface.triangles.end(), model.fringe.triangles.begin(),
                           model.fringe.triangles.end());
  return surface;
}

namespace {

// The DC of the specimen's surface at its draped and flat positions.
DrapeCoefficient CoefficientOf(const SpecimenSurface& draped, const SpecimenSurface& flat,
                               double disc_radius, const ShadowOptions& options) {
  DrapeCoefficient dc;
  dc.shadow = ProjectedArea(draped.points, draped.triangles, options);
  dc.flat_area = ProjectedArea(flat.points, flat.triangles, options).area;
  dc.ratio = dc.flat_area > 0.0 ? dc.shadow.area / dc.flat_area : 0.0;
  dc.cusick = std::numeric_limits<double>::quiet_NaN();
  if (disc_radius > 0.0) dc.cusick = CusickCoefficient(dc.shadow.area, dc.flat_area, disc_radius);
  return dc;
}

// The support (src/model/obstacle_kinds.h: a disk, a pin) of largest radius, or null.
const ObstacleSpec* WidestSupport(const Scene& scene) {
  const ObstacleSpec* widest = nullptr;
  for (const ObstacleSpec& obstacle : scene.obstacles) {
    if (!ObstacleKindOf(obstacle).support) continue;
    if (widest == nullptr || obstacle.radius > widest->radius) widest = &obstacle;
  }
  return widest;
}

double Cross(double ax, double ay, double bx, double by) { return ax * by - ay * bx; }

// Raises radius[k] to the distance from the centre (the origin here) at which ray k leaves the
// segment p–q, for the rays the segment can meet (those within the angle it subtends).
void ExtendAlongSegment(double px, double py, double qx, double qy, std::vector<double>* radius) {
  const int angles = static_cast<int>(radius->size());
  const double step = 2.0 * M_PI / angles;
  const bool p_at_centre = px == 0.0 && py == 0.0;
  if (p_at_centre && qx == 0.0 && qy == 0.0) return;
  const double start = p_at_centre ? std::atan2(qy, qx) : std::atan2(py, px);
  const double span = p_at_centre ? 0.0 : std::atan2(Cross(px, py, qx, qy), px * qx + py * qy);
  int first = 0, last = angles - 1;  // a segment through the centre can meet every ray
  if (std::abs(span) < M_PI - 1e-9) {
    first = static_cast<int>(std::floor((start + std::min(0.0, span)) / step));
    last = static_cast<int>(std::ceil((start + std::max(0.0, span)) / step));
  }
  for (int k = first; k <= last; ++k) {
    const int ray = ((k % angles) + angles) % angles;
    const double dx = std::cos(step * ray), dy = std::sin(step * ray);
    // Signed distances of p and q from the ray's line; the segment meets the line where they
    // change sign, at the convex combination below (stable even for a segment almost along it).
    const double a = Cross(dx, dy, px, py), b = Cross(dx, dy, qx, qy);
    const double along_p = dx * px + dy * py, along_q = dx * qx + dy * qy;
    double t = -1.0;
    if (a == 0.0 && b == 0.0) {
      t = std::max(along_p, along_q);  // on the line
    } else if ((a <= 0.0 && b >= 0.0) || (a >= 0.0 && b <= 0.0)) {
      const double s = a / (a - b);
      t = (1.0 - s) * along_p + s * along_q;
    }
    if (t > (*radius)[ray]) (*radius)[ray] = t;
  }
}

// Circular convolution with a Gaussian of `sigma` samples, truncated at ±4σ and renormalised.
std::vector<double> SmoothPeriodic(const std::vector<double>& values, double sigma) {
  const int n = static_cast<int>(values.size());
  if (!(sigma > 0.0) || n < 3) return values;
  const int reach = std::min(n / 2, static_cast<int>(std::ceil(4.0 * sigma)));
  std::vector<double> weights(2 * reach + 1);
  double total = 0.0;
  for (int j = -reach; j <= reach; ++j) {
    weights[j + reach] = std::exp(-0.5 * j * j / (sigma * sigma));
    total += weights[j + reach];
  }
  std::vector<double> smoothed(n, 0.0);
  for (int i = 0; i < n; ++i) {
    for (int j = -reach; j <= reach; ++j) {
      smoothed[i] += weights[j + reach] * values[((i + j) % n + n) % n];
    }
    smoothed[i] /= total;
  }
  return smoothed;
}

// Topographic prominence of sample `peak` on a periodic profile: its height above the higher of
// the lowest values met walking each way before reaching a strictly higher sample (or going all
// the way round).
double Prominence(const std::vector<double>& values, int peak) {
  const int n = static_cast<int>(values.size());
  double lowest[2] = {values[peak], values[peak]};
  for (int side = 0; side < 2; ++side) {
    const int direction = side == 0 ? -1 : 1;
    for (int step = 1; step < n; ++step) {
      const double value = values[((peak + direction * step) % n + n) % n];
      if (value > values[peak]) break;
      lowest[side] = std::min(lowest[side], value);
    }
  }
  return values[peak] - std::max(lowest[0], lowest[1]);
}

}  // namespace

DrapeCoefficient ComputeDrapeCoefficient(const Model& model, double disc_radius,
                                         const ShadowOptions& options) {
  return CoefficientOf(SurfaceAt(model, model.positions), SurfaceAt(model, model.initial),
                       disc_radius, options);
}

RadialProfile ComputeRadialProfile(const std::vector<double>& positions,
                                   const std::vector<std::array<int, 3>>& triangles,
                                   const std::array<double, 2>& centre, int angles) {
  assert(angles >= 3);
  RadialProfile profile;
  profile.centre = centre;
  profile.radius.assign(angles, 0.0);
  for (int k = 0; k < angles; ++k) profile.theta.push_back(2.0 * M_PI * k / angles);
  auto x = [&](int v) { return NodeAt(positions, v).x() - centre[0]; };
  auto y = [&](int v) { return NodeAt(positions, v).y() - centre[1]; };
  for (const auto& t : triangles) {
    if (Cross(x(t[1]) - x(t[0]), y(t[1]) - y(t[0]), x(t[2]) - x(t[0]), y(t[2]) - y(t[0])) == 0.0) {
      continue;  // seen edge-on: casts no shadow
    }
    for (int e = 0; e < 3; ++e) {
      const int a = t[e], b = t[(e + 1) % 3];
      ExtendAlongSegment(x(a), y(a), x(b), y(b), &profile.radius);
    }
  }
  return profile;
}

Folds CountFolds(const std::vector<double>& profile, const FoldOptions& options) {
  Folds folds;
  const int n = static_cast<int>(profile.size());
  if (n == 0) return folds;
  const double degrees_per_sample = 360.0 / n;
  folds.smoothed = SmoothPeriodic(profile, options.smoothing_deg / degrees_per_sample);
  const auto& s = folds.smoothed;
  const auto [low, high] = std::minmax_element(s.begin(), s.end());
  double mean = 0.0;
  for (double r : s) mean += r / n;
  const double threshold = std::max(
      options.relative_prominence * (*high - *low),
      options.absolute_prominence * (options.length_scale > 0.0 ? options.length_scale : mean));
  for (int i = 0; i < n; ++i) {
    const double before = s[(i + n - 1) % n], after = s[(i + 1) % n];
    if (!(s[i] > before && s[i] >= after)) continue;
    const double prominence = Prominence(s, i);
    if (!(prominence > 0.0 && prominence >= threshold)) continue;
    // The crest between samples: the vertex of the parabola through the three samples.
    const double curvature = before - 2.0 * s[i] + after;
    const double shift = curvature < 0.0 ? 0.5 * (before - after) / curvature : 0.0;
    folds.angles_deg.push_back(std::fmod((i + shift) * degrees_per_sample + 360.0, 360.0));
  }
  folds.count = static_cast<int>(folds.angles_deg.size());
  return folds;
}

// The centre of the widest support (a drape tester's disk, a pin), else of the flat fabric.
std::array<double, 2> ProfileCentre(const Scene& scene, const Model& model) {
  const ObstacleSpec* support = WidestSupport(scene);
  if (support != nullptr) return {support->center.x(), support->center.y()};
  // Area-weighted centroid of the flat triangles.
  double area = 0.0, cx = 0.0, cy = 0.0;
  const auto& p = model.initial;
  for (const auto& t : model.triangles) {
    const double a = 0.5 * std::abs(Cross(NodeAt(p, t[1]).x() - NodeAt(p, t[0]).x(),
                                          NodeAt(p, t[1]).y() - NodeAt(p, t[0]).y(),
                                          NodeAt(p, t[2]).x() - NodeAt(p, t[0]).x(),
                                          NodeAt(p, t[2]).y() - NodeAt(p, t[0]).y()));
    area += a;
    const Eigen::Vector3d centroid = (NodeAt(p, t[0]) + NodeAt(p, t[1]) + NodeAt(p, t[2])) / 3.0;
    cx += a * centroid.x();
    cy += a * centroid.y();
  }
  if (area > 0.0) return {cx / area, cy / area};
  return {0.0, 0.0};
}

DrapeAnalysis AnalyseDrape(const Scene& scene, const Model& model) {
  DrapeAnalysis analysis;
  analysis.disc_radius = DiscRadius(scene);
  const SpecimenSurface draped = SurfaceAt(model, model.positions);
  const SpecimenSurface flat = SurfaceAt(model, model.initial);
  analysis.coefficient = CoefficientOf(draped, flat, analysis.disc_radius, {});
  const std::array<double, 2> centre = ProfileCentre(scene, model);
  analysis.profile = ComputeRadialProfile(draped.points, draped.triangles, centre);
  analysis.flat_profile = ComputeRadialProfile(flat.points, flat.triangles, centre);
  const auto& radius = analysis.profile.radius;
  const int n = static_cast<int>(radius.size());
  analysis.radius_min = *std::min_element(radius.begin(), radius.end());
  analysis.radius_max = *std::max_element(radius.begin(), radius.end());
  for (double r : radius) analysis.radius_mean += r / n;
  const double disc = analysis.disc_radius;
  for (int k = 0; k < n; ++k) {
    const double flat_overhang = analysis.flat_profile.radius[k] - disc;
    analysis.overhang.push_back(flat_overhang > 0.0 ? (radius[k] - disc) / flat_overhang : 1.0);
  }
  FoldOptions folds;
  folds.length_scale = 1.0;  // the flat overhang
  analysis.folds = CountFolds(analysis.overhang, folds);
  return analysis;
}

double DiscRadius(const Scene& scene) {
  const ObstacleSpec* support = WidestSupport(scene);
  return support != nullptr ? support->radius : 0.0;
}

bool HasDrapeCoefficient(const Scene& scene, const Model& model) {
  bool disc_mesh = false;  // a circular specimen
  switch (scene.mesh.kind) {
    case MeshSpec::Kind::kCircle:
    case MeshSpec::Kind::kArc:
      disc_mesh = true;
      break;
    case MeshSpec::Kind::kGrid:
    case MeshSpec::Kind::kChain:
    case MeshSpec::Kind::kFile:
      break;
  }
  return !model.triangles.empty() && (DiscRadius(scene) > 0.0 || disc_mesh);
}

}  // namespace drape
