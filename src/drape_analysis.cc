#include "src/drape_analysis.h"

#include <cairo.h>

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <memory>

namespace drape {

namespace {

constexpr double kPi = 3.14159265358979323846;

struct Bounds {
  double x0 = std::numeric_limits<double>::infinity(), y0 = x0;
  double x1 = -x0, y1 = -x0;
};

Bounds ProjectedBounds(const std::vector<double>& positions,
                       const std::vector<std::array<int, 3>>& triangles) {
  Bounds b;
  for (const auto& t : triangles) {
    for (int v : t) {
      b.x0 = std::min(b.x0, positions[3 * v]);
      b.x1 = std::max(b.x1, positions[3 * v]);
      b.y0 = std::min(b.y0, positions[3 * v + 1]);
      b.y1 = std::max(b.y1, positions[3 * v + 1]);
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
  auto px = [&](int v) { return margin + (positions[3 * v] - b.x0) / pixel; };
  auto py = [&](int v) { return margin + (positions[3 * v + 1] - b.y0) / pixel; };
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

DrapeCoefficient ComputeDrapeCoefficient(const Model& model, double disc_radius,
                                         const ShadowOptions& options) {
  DrapeCoefficient dc;
  dc.shadow = ProjectedArea(model.positions, model.triangles, options);
  dc.flat_area = ProjectedArea(model.initial, model.triangles, options).area;
  dc.ratio = dc.flat_area > 0.0 ? dc.shadow.area / dc.flat_area : 0.0;
  dc.cusick = std::numeric_limits<double>::quiet_NaN();
  if (disc_radius > 0.0) {
    const double disc = kPi * disc_radius * disc_radius;
    dc.cusick = (dc.shadow.area - disc) / (dc.flat_area - disc);
  }
  return dc;
}

double DiscRadius(const Scene& scene) {
  for (const auto& obstacle : scene.obstacles) {
    if (obstacle.kind == ObstacleSpec::Kind::kDisk) return obstacle.radius;
  }
  return 0.0;
}

bool HasDrapeCoefficient(const Scene& scene, const Model& model) {
  const bool disc_mesh =
      scene.mesh.kind == MeshSpec::Kind::kCircle || scene.mesh.kind == MeshSpec::Kind::kArc;
  return !model.triangles.empty() && (DiscRadius(scene) > 0.0 || disc_mesh);
}

}  // namespace drape
