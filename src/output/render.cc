#include "src/output/render.h"

#include <cairo.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <sstream>
#include <stdexcept>

#include "src/model/obstacle_kinds.h"
#include "src/output/json.h"
#include "src/output/png_text.h"

namespace drape {

namespace {

using Vec3 = Eigen::Vector3d;
using SurfacePtr = std::unique_ptr<cairo_surface_t, decltype(&cairo_surface_destroy)>;
using ContextPtr = std::unique_ptr<cairo_t, decltype(&cairo_destroy)>;

// ---- shared drawing helpers ---------------------------------------------------------------------

cairo_status_t WriteToStream(void* closure, const unsigned char* data, unsigned int length) {
  auto* out = static_cast<std::ostream*>(closure);
  out->write(reinterpret_cast<const char*>(data), length);
  return *out ? CAIRO_STATUS_SUCCESS : CAIRO_STATUS_WRITE_ERROR;
}

// The picture as PNG, with drape's version in it (src/output/png_text.h).
void WritePng(cairo_surface_t* surface, std::ostream& png) {
  cairo_surface_flush(surface);
  std::ostringstream bytes;
  const cairo_status_t status = cairo_surface_write_to_png_stream(surface, WriteToStream, &bytes);
  if (status != CAIRO_STATUS_SUCCESS) {
    throw std::runtime_error(std::string("cairo: ") + cairo_status_to_string(status));
  }
  png << PngWithDrapeVersion(bytes.str());
}

void Text(cairo_t* cr, double x, double y, const std::string& text, double size, bool bold = false,
          Rgb colour = {0.1, 0.1, 0.1}) {
  cairo_select_font_face(cr, "DejaVu Sans", CAIRO_FONT_SLANT_NORMAL,
                         bold ? CAIRO_FONT_WEIGHT_BOLD : CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr, size);
  cairo_set_source_rgb(cr, colour.r, colour.g, colour.b);
  cairo_move_to(cr, x, y);
  cairo_show_text(cr, text.c_str());
}

double TextWidth(cairo_t* cr, const std::string& text, double size) {
  cairo_select_font_face(cr, "DejaVu Sans", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr, size);
  cairo_text_extents_t extents;
  cairo_text_extents(cr, text.c_str(), &extents);
  return extents.x_advance;
}

std::string Format(const char* format, double value) {
  char text[64];
  std::snprintf(text, sizeof text, format, value);
  return text;
}

// A round length (1, 2 or 5 × 10^k m) that is about `target_px` pixels long at `px_per_m`.
double RoundLength(double px_per_m, double target_px) {
  const double raw = target_px / px_per_m;
  const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
  const double ratio = raw / magnitude;
  return (ratio < 1.5 ? 1.0 : ratio < 3.5 ? 2.0 : ratio < 7.5 ? 5.0 : 10.0) * magnitude;
}

// "5 cm", "2 mm", "1 m": the unit that keeps the number between 1 and 999.
std::string LengthLabel(double metres) {
  if (metres >= 1.0) return Format("%g m", metres);
  if (metres >= 0.01) return Format("%g cm", std::round(metres * 1000.0) / 10.0);
  return Format("%g mm", std::round(metres * 1e4) / 10.0);
}

// A horizontal scale bar with end ticks, its label centred above; (x, y) is its left end.
void ScaleBar(cairo_t* cr, double x, double y, double px_per_m, double target_px) {
  const double length = RoundLength(px_per_m, target_px);
  const double pixels = length * px_per_m;
  cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
  cairo_set_line_width(cr, 2.0);
  cairo_move_to(cr, x, y - 5);
  cairo_line_to(cr, x, y);
  cairo_line_to(cr, x + pixels, y);
  cairo_line_to(cr, x + pixels, y - 5);
  cairo_stroke(cr);
  const std::string label = LengthLabel(length);
  Text(cr, x + 0.5 * (pixels - TextWidth(cr, label, 13)), y - 8, label, 13);
}

// ---- the 3-D view -------------------------------------------------------------------------------

// An orthographic camera: screen x along `right`, screen y along −`up`, depth along `forward`.
struct Camera {
  Vec3 right, up, forward;
  double scale = 1.0;     // pixels per metre
  double u0 = 0, v0 = 0;  // the picture-plane point drawn at (cx, cy)
  double cx = 0, cy = 0;  // pixels
  Eigen::Vector2d Pixel(const Vec3& p) const {
    return {cx + scale * (p.dot(right) - u0), cy - scale * (p.dot(up) - v0)};
  }
  double Depth(const Vec3& p) const { return p.dot(forward); }
};

Camera Orient(double azimuth_deg, double elevation_deg) {
  const double az = azimuth_deg * M_PI / 180.0, el = elevation_deg * M_PI / 180.0;
  const Vec3 to_eye(std::cos(el) * std::cos(az), std::cos(el) * std::sin(az), std::sin(el));
  Camera camera;
  camera.forward = -to_eye;
  camera.right = camera.forward.cross(Vec3::UnitZ()).normalized();
  camera.up = camera.right.cross(camera.forward);
  return camera;
}

// Something to paint: a polygon (3 or 4 points) or a segment (2 points).
struct Primitive {
  std::vector<Vec3> points;
  Rgb colour;
  bool fabric = false;
  bool background = false;  // painted first whatever its depth (a plane)
  double depth_bias = 0.0;  // m, added to the depth for sorting (pushes obstacles back)
  double depth = 0.0;
};

const double kDash[] = {6.0, 4.0};
const Rgb kFloor{0.86, 0.86, 0.84};
// The legend: its marks' left edge this far from the picture's right edge; entry k's text baseline.
constexpr double kLegendInset = 210.0;
double LegendRow(int k) { return 24.0 + 18.0 * k; }
const Rgb& kFabricFront = StyleOf(DrawnKind::kUpperFace).colour;
const Rgb& kFabricBack = StyleOf(DrawnKind::kLowerFace).colour;
const Rgb& kObstacle = StyleOf(DrawnKind::kObstacle).colour;
const Rgb& kChain = StyleOf(DrawnKind::kChain).colour;

Vec3 Node(const Model& model, int k) { return model.position(k); }

struct Box3 {
  Vec3 min = Vec3::Constant(std::numeric_limits<double>::infinity());
  Vec3 max = -min;
  void Add(const Vec3& p) {
    min = min.cwiseMin(p);
    max = max.cwiseMax(p);
  }
  double Extent() const { return (max - min).maxCoeff(); }
  Vec3 Centre() const { return 0.5 * (min + max); }
};

// A grid of quads spanning origin + s·a + t·b, s, t ∈ [0, 1], `cells` per side.
void AddPatch(const Vec3& origin, const Vec3& a, const Vec3& b, int cells, Rgb colour,
              std::vector<Primitive>* out) {
  for (int i = 0; i < cells; ++i) {
    for (int j = 0; j < cells; ++j) {
      auto at = [&](int di, int dj) {
        return Vec3(origin + a * double(i + di) / cells + b * double(j + dj) / cells);
      };
      out->push_back({{at(0, 0), at(1, 0), at(1, 1), at(0, 1)}, colour});
    }
  }
}

// A vertical cylinder's side from z_top down by `height`, and its top as a fan of rings.
void AddCylinder(const Vec3& top_centre, double radius, double height, bool cap, Rgb colour,
                 std::vector<Primitive>* out) {
  const int sides = 48, rings = 4;
  for (int k = 0; k < sides; ++k) {
    const double a0 = 2 * M_PI * k / sides, a1 = 2 * M_PI * (k + 1) / sides;
    const Vec3 p0 = top_centre + radius * Vec3(std::cos(a0), std::sin(a0), 0);
    const Vec3 p1 = top_centre + radius * Vec3(std::cos(a1), std::sin(a1), 0);
    const Vec3 down(0, 0, -height);
    out->push_back({{p0, p1, p1 + down, p0 + down}, colour});
    if (!cap) continue;
    for (int ring = 0; ring < rings; ++ring) {
      const double r0 = double(ring) / rings, r1 = double(ring + 1) / rings;
      const Vec3 q0 = top_centre + r0 * (p0 - top_centre), q1 = top_centre + r0 * (p1 - top_centre);
      const Vec3 s0 = top_centre + r1 * (p0 - top_centre), s1 = top_centre + r1 * (p1 - top_centre);
      out->push_back({{q0, s0, s1, q1}, colour});
    }
  }
}

void AddSphere(const Vec3& centre, double radius, Rgb colour, std::vector<Primitive>* out) {
  const int slices = 32, stacks = 16;
  auto at = [&](int i, int j) {
    const double phi = 2 * M_PI * i / slices, theta = M_PI * j / stacks;
    return Vec3(centre + radius * Vec3(std::sin(theta) * std::cos(phi),
                                       std::sin(theta) * std::sin(phi), std::cos(theta)));
  };
  for (int i = 0; i < slices; ++i) {
    for (int j = 0; j < stacks; ++j) {
      out->push_back({{at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)}, colour});
    }
  }
}

void AddBox(const Vec3& lo, const Vec3& hi, Rgb colour, std::vector<Primitive>* out) {
  const Vec3 d = hi - lo;
  const Vec3 ex(d.x(), 0, 0), ey(0, d.y(), 0), ez(0, 0, d.z());
  const int cells = 6;
  AddPatch(lo, ex, ey, cells, colour, out);
  AddPatch(lo + ez, ex, ey, cells, colour, out);
  AddPatch(lo, ex, ez, cells, colour, out);
  AddPatch(lo + ey, ex, ez, cells, colour, out);
  AddPatch(lo, ey, ez, cells, colour, out);
  AddPatch(lo + ex, ey, ez, cells, colour, out);
}

// A plane as a square patch 1.4 × the fabric's extent around the point of the plane nearest the
// fabric's centre, drawn behind everything.
void AddPlanePatch(const Vec3& point, const Vec3& normal, const Box3& fabric,
                   std::vector<Primitive>* out) {
  const double extent = std::max(fabric.Extent(), 1e-9);
  const Vec3 foot = fabric.Centre() - (fabric.Centre() - point).dot(normal) * normal;
  const Vec3 a =
      (std::abs(normal.z()) < 0.9 ? normal.cross(Vec3::UnitZ()) : normal.cross(Vec3::UnitX()))
          .normalized() *
      1.4 * extent;
  const Vec3 b = normal.cross(a);
  const size_t first = out->size();
  AddPatch(foot - 0.5 * a - 0.5 * b, a, b, 10, kFloor, out);
  for (size_t k = first; k < out->size(); ++k) (*out)[k].background = true;
}

void AddPart(const ObstaclePart& part, const Box3& fabric, std::vector<Primitive>* out) {
  switch (part.shape) {
    case ObstaclePart::Shape::kSphere:
      AddSphere(part.a, part.radius, kObstacle, out);
      break;
    case ObstaclePart::Shape::kCylinder:
      AddCylinder(part.a, part.radius, part.height, part.capped, kObstacle, out);
      break;
    case ObstaclePart::Shape::kBox:
      AddBox(part.a, part.b, kObstacle, out);
      break;
    case ObstaclePart::Shape::kPlane:
      AddPlanePatch(part.a, part.b, fabric, out);
      break;
    case ObstaclePart::Shape::kSurface:
      for (const auto& face : part.surface->faces()) {
        const auto& v = part.surface->vertices();
        out->push_back({{v[face[0]], v[face[1]], v[face[2]]}, kObstacle});
      }
      break;
  }
}

// The obstacles as shaded polygons, each drawn as its kind says (src/model/obstacle_kinds.h),
// unbounded or support-like parts sized from the fabric's bounding box `fabric`.
void AddObstacles(const std::vector<ObstacleSpec>& obstacles, const Box3& fabric, double floor_z,
                  std::vector<Primitive>* out) {
  const DrawingFrame frame{std::max(fabric.Extent(), 1e-9), floor_z};
  for (const ObstacleSpec& o : obstacles) {
    for (const ObstaclePart& part : ObstacleKindOf(o).draw(o, frame)) AddPart(part, fabric, out);
  }
}

// Mean length of the fabric's edges (triangles, else line elements), m.
double MeanEdgeLength(const Model& model) {
  double total = 0.0;
  int count = 0;
  for (const auto& t : model.triangles) {
    for (int e = 0; e < 3; ++e, ++count)
      total += (Node(model, t[e]) - Node(model, t[(e + 1) % 3])).norm();
  }
  for (const auto& e : model.edges) {
    total += (Node(model, e[0]) - Node(model, e[1])).norm();
    ++count;
  }
  return count ? total / count : 0.0;
}

// Frames the camera: the fabric, its floor shadow, and the obstacles within 30% of the fabric's
// extent around it (a large table or floor does not shrink the fabric to a dot).
void Frame(const std::vector<Primitive>& primitives, const Box3& fabric, int width, int height,
           double top, double bottom, Camera* camera) {
  const Vec3 margin = Vec3::Constant(0.3 * fabric.Extent());
  double u_min = std::numeric_limits<double>::infinity(), u_max = -u_min, v_min = u_min,
         v_max = -u_min;
  for (const Primitive& primitive : primitives) {
    for (const Vec3& p : primitive.points) {
      const Vec3 q =
          primitive.fabric ? p : p.cwiseMax(fabric.min - margin).cwiseMin(fabric.max + margin);
      u_min = std::min(u_min, q.dot(camera->right));
      u_max = std::max(u_max, q.dot(camera->right));
      v_min = std::min(v_min, q.dot(camera->up));
      v_max = std::max(v_max, q.dot(camera->up));
    }
  }
  const double side = 40.0;
  const double span_u = std::max(u_max - u_min, 1e-9), span_v = std::max(v_max - v_min, 1e-9);
  camera->scale = std::min((width - 2 * side) / span_u, (height - top - bottom) / span_v);
  camera->u0 = 0.5 * (u_min + u_max);
  camera->v0 = 0.5 * (v_min + v_max);
  camera->cx = 0.5 * width;
  camera->cy = top + 0.5 * (height - top - bottom);
}

// The floor under the fabric: 5% of its extent below its lowest point, or a horizontal plane
// obstacle under it. NaN (no floor drawn) when a solid obstacle (box, cylinder, sphere) reaches
// lower: its shadow would float beside it.
double FloorHeight(const std::vector<ObstacleSpec>& obstacles, const Box3& fabric) {
  for (const ObstacleSpec& o : obstacles) {
    for (const ObstaclePart& part : ObstacleKindOf(o).draw(o, DrawingFrame{})) {
      if (part.shape == ObstaclePart::Shape::kPlane && part.b.z() > 0.999 &&
          part.a.z() <= fabric.min.z()) {
        return part.a.z();
      }
    }
  }
  const double z = fabric.min.z() - 0.05 * fabric.Extent();
  for (const ObstacleSpec& o : obstacles) {
    const double bottom = ObstacleKindOf(o).lowest_z(o);
    if (std::isfinite(bottom) && bottom < z) return std::numeric_limits<double>::quiet_NaN();
  }
  return z;
}

// The fabric's vertical projection on the floor.
void AddFloorShadow(const Model& model, double floor_z, std::vector<Primitive>* floor) {
  for (const auto& t : model.triangles) {
    Primitive shadow{{}, kFloor, true};
    for (int v : t) {
      shadow.points.push_back({model.position(v).x(), model.position(v).y(), floor_z});
    }
    floor->push_back(shadow);
  }
}

void PathOf(cairo_t* cr, const Camera& camera, const std::vector<Vec3>& points) {
  for (size_t k = 0; k < points.size(); ++k) {
    const Eigen::Vector2d p = camera.Pixel(points[k]);
    if (k == 0)
      cairo_move_to(cr, p.x(), p.y());
    else
      cairo_line_to(cr, p.x(), p.y());
  }
}

// Lambert shading of a polygon: ambient 0.35 + diffuse 0.65 |n·l| (two-sided); the fabric's two
// faces in two colours.
Rgb Shade(const Primitive& primitive, const Camera& camera, const Vec3& light) {
  const auto& p = primitive.points;
  Vec3 normal = Vec3::Zero();  // Newell's normal: robust to a collapsed edge (a sphere's pole)
  for (size_t k = 0; k < p.size(); ++k) normal += p[k].cross(p[(k + 1) % p.size()]);
  normal.normalize();
  if (!normal.allFinite()) return primitive.colour;
  Rgb base = primitive.colour;
  if (primitive.fabric) base = normal.dot(camera.forward) <= 0.0 ? kFabricFront : kFabricBack;
  const double intensity = 0.35 + 0.65 * std::abs(normal.dot(light));
  return {base.r * intensity, base.g * intensity, base.b * intensity};
}

void PaintPrimitives(cairo_t* cr, const Camera& camera, std::vector<Primitive>* primitives,
                     double edge_px) {
  for (Primitive& primitive : *primitives) {
    primitive.depth = primitive.depth_bias;
    for (const Vec3& p : primitive.points)
      primitive.depth += camera.Depth(p) / primitive.points.size();
  }
  std::stable_sort(primitives->begin(), primitives->end(),
                   [](const Primitive& a, const Primitive& b) { return a.depth > b.depth; });
  const Vec3 light = (-0.3 * camera.right + 0.5 * camera.up - 0.8 * camera.forward).normalized();
  const bool draw_edges = edge_px >= 8.0;
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
  for (const Primitive& primitive : *primitives) {
    PathOf(cr, camera, primitive.points);
    if (primitive.points.size() == 2) {
      cairo_set_source_rgb(cr, primitive.colour.r, primitive.colour.g, primitive.colour.b);
      cairo_set_line_width(cr, 2.5);
      cairo_stroke(cr);
      continue;
    }
    cairo_close_path(cr);
    const Rgb colour = Shade(primitive, camera, light);
    cairo_set_source_rgb(cr, colour.r, colour.g, colour.b);
    // Stroking with the fill colour hides the hairline seams between antialiased neighbours.
    cairo_fill_preserve(cr);
    cairo_set_line_width(cr, 0.6);
    cairo_stroke_preserve(cr);
    if (draw_edges && primitive.fabric) {
      cairo_set_source_rgba(cr, 0.0, 0.0, 0.0, 0.25);
      cairo_set_line_width(cr, 0.6);
      cairo_stroke(cr);
    }
    cairo_new_path(cr);
  }
}

// The vertical projection of the fabric (union of its triangles), painted in one fill.
void PaintFloorShadow(cairo_t* cr, const Camera& camera, const std::vector<Primitive>& floor) {
  if (floor.empty()) return;
  cairo_set_fill_rule(cr, CAIRO_FILL_RULE_WINDING);
  for (const Primitive& triangle : floor) {
    std::vector<Vec3> points = triangle.points;
    const Eigen::Vector2d a = camera.Pixel(points[0]), b = camera.Pixel(points[1]),
                          c = camera.Pixel(points[2]);
    const double cross = (b - a).x() * (c - a).y() - (b - a).y() * (c - a).x();
    if (cross == 0.0) continue;
    if (cross < 0.0) std::swap(points[1], points[2]);  // one winding: the union fills once
    PathOf(cr, camera, points);
    cairo_close_path(cr);
  }
  cairo_set_source_rgba(cr, 0.0, 0.0, 0.0, 0.2);  // darkens white paper and a floor alike
  cairo_fill(cr);
}

// Held coordinates of node k: 3 fully fixed (2 in 2-D, where every node's y is held), else 1–2.
int HeldCoordinates(const Model& model, int k) {
  const bool y_counts = model.dimension != 2;
  return model.fixed[3 * k] + (y_counts ? model.fixed[3 * k + 1] : 0) + model.fixed[3 * k + 2];
}

// Fixed nodes: black squares, hollow where only partly fixed; many of them (a clamped region) as
// small dots, so that they do not hide the fabric.
void PaintFixedNodes(cairo_t* cr, const Camera& camera, const Model& model) {
  int count = 0;
  for (int k = 0; k < model.num_nodes; ++k) count += HeldCoordinates(model, k) > 0;
  const bool many = count > 40;
  for (int k = 0; k < model.num_nodes; ++k) {
    const int held = HeldCoordinates(model, k);
    if (held == 0) continue;
    const bool fully = held == (model.dimension != 2 ? 3 : 2);
    const Eigen::Vector2d p = camera.Pixel(Node(model, k));
    if (many) {
      cairo_arc(cr, p.x(), p.y(), 1.5, 0, 2 * M_PI);
      cairo_set_source_rgba(cr, 0, 0, 0, fully ? 0.8 : 0.45);
      cairo_fill(cr);
      continue;
    }
    cairo_rectangle(cr, p.x() - 3.5, p.y() - 3.5, 7, 7);
    const Rgb& black = StyleOf(fully ? DrawnKind::kFixedNode : DrawnKind::kPartlyFixedNode).colour;
    cairo_set_source_rgb(cr, black.r, black.g, black.b);
    if (fully) {
      cairo_fill(cr);
    } else {
      cairo_set_line_width(cr, 1.5);
      cairo_stroke(cr);
    }
  }
}

// Chain nodes as small dots, when there are few enough to tell apart.
void PaintChainNodes(cairo_t* cr, const Camera& camera, const Model& model, double edge_px) {
  if (!model.triangles.empty() || model.edges.empty() || edge_px < 8.0) return;
  cairo_set_source_rgb(cr, kChain.r, kChain.g, kChain.b);
  for (int k = 0; k < model.num_nodes; ++k) {
    const Eigen::Vector2d p = camera.Pixel(Node(model, k));
    cairo_arc(cr, p.x(), p.y(), 2.5, 0, 2 * M_PI);
    cairo_fill(cr);
  }
}

// x, y, z arrows in the lower left corner, as the camera sees them.
void PaintAxes(cairo_t* cr, const Camera& camera, double x, double y) {
  const char* names[3] = {"x", "y", "z"};
  const Rgb colours[3] = {{0.75, 0.15, 0.1}, {0.1, 0.55, 0.15}, {0.1, 0.25, 0.75}};
  for (int axis = 0; axis < 3; ++axis) {
    const Vec3 direction = Vec3::Unit(axis);
    const double du = 28 * direction.dot(camera.right), dv = -28 * direction.dot(camera.up);
    if (std::hypot(du, dv) < 3) continue;  // along the line of sight
    cairo_set_source_rgb(cr, colours[axis].r, colours[axis].g, colours[axis].b);
    cairo_set_line_width(cr, 2);
    cairo_move_to(cr, x, y);
    cairo_line_to(cr, x + du, y + dv);
    cairo_stroke(cr);
    Text(cr, x + 1.3 * du - 4, y + 1.3 * dv + 5, names[axis], 13, true, colours[axis]);
  }
}

// Planes go to `background`; the other obstacles join `solids`, pushed back for the depth sort
// by two fabric edges and their own size (see render.h).
void SplitObstacles(const std::vector<Primitive>& obstacles, double edge,
                    std::vector<Primitive>* background, std::vector<Primitive>* solids) {
  for (Primitive o : obstacles) {
    if (o.background) {
      background->push_back(o);
      continue;
    }
    double size = 0.0;
    for (const Vec3& p : o.points) size = std::max(size, (p - o.points[0]).norm());
    o.depth_bias = 2.0 * edge + size;
    solids->push_back(o);
  }
}

}  // namespace

namespace {

// The key of drape.png's colours and marks, top right (DrapeLegend).
void PaintLegend(cairo_t* cr, const Scene& scene, const Model& model, int width) {
  const std::vector<DrawnKind> kinds = DrapeLegend(scene, model);
  const double x = width - kLegendInset;
  for (size_t k = 0; k < kinds.size(); ++k) {
    const DrawnStyle& entry = StyleOf(kinds[k]);
    const double y = LegendRow(static_cast<int>(k));
    cairo_set_source_rgb(cr, entry.colour.r, entry.colour.g, entry.colour.b);
    if (entry.mark == LegendMark::kLine) {
      cairo_move_to(cr, x, y - 4);
      cairo_line_to(cr, x + 14, y - 4);
      cairo_set_line_width(cr, 2.5);
      cairo_stroke(cr);
    } else if (entry.mark == LegendMark::kHollowSquare) {
      cairo_rectangle(cr, x + 3.5, y - 7.5, 7, 7);
      cairo_set_line_width(cr, 1.5);
      cairo_stroke(cr);
    } else {
      const double side = entry.mark == LegendMark::kFilledSquare ? 7.0 : 12.0;
      cairo_rectangle(cr, x + 7 - side / 2, y - 4 - side / 2, side, side);
      cairo_fill(cr);
    }
    Text(cr, x + 22, y, entry.label, 12);
  }
}

}  // namespace

const std::vector<DrawnStyle>& DrawnStyles() {
  static const std::vector<DrawnStyle> styles = {
      {DrawnKind::kUpperFace,
       "upper face (as it lay flat)",
       {0.33, 0.56, 0.90},
       LegendMark::kSwatch},
      {DrawnKind::kLowerFace, "lower face", {0.96, 0.76, 0.50}, LegendMark::kSwatch},
      {DrawnKind::kChain, "chain", {0.12, 0.25, 0.55}, LegendMark::kLine},
      {DrawnKind::kFixedNode, "fixed node", {0, 0, 0}, LegendMark::kFilledSquare},
      {DrawnKind::kPartlyFixedNode, "partly fixed node", {0, 0, 0}, LegendMark::kHollowSquare},
      {DrawnKind::kObstacle, "obstacle", {0.62, 0.62, 0.60}, LegendMark::kSwatch}};
  return styles;
}

const DrawnStyle& StyleOf(DrawnKind kind) {
  for (const DrawnStyle& style : DrawnStyles()) {
    if (style.kind == kind) return style;
  }
  assert(false && "every DrawnKind has a row in DrawnStyles");
  return DrawnStyles().front();
}

std::vector<DrawnKind> DrapeLegend(const Scene& scene, const Model& model) {
  bool fully = false, partly = false;
  const int all = model.dimension != 2 ? 3 : 2;
  for (int k = 0; k < model.num_nodes; ++k) {
    const int held = HeldCoordinates(model, k);
    fully = fully || held == all;
    partly = partly || (held > 0 && held < all);
  }
  std::vector<DrawnKind> kinds;
  for (const DrawnStyle& style : DrawnStyles()) {
    const DrawnKind kind = style.kind;
    const bool drawn = ((kind == DrawnKind::kUpperFace || kind == DrawnKind::kLowerFace) &&
                        !model.triangles.empty()) ||
                       (kind == DrawnKind::kChain && !model.edges.empty()) ||
                       (kind == DrawnKind::kFixedNode && fully) ||
                       (kind == DrawnKind::kPartlyFixedNode && partly) ||
                       (kind == DrawnKind::kObstacle && !scene.obstacles.empty());
    if (drawn) kinds.push_back(kind);
  }
  return kinds;
}

std::array<int, 2> LegendMarkPixel(int index, LegendMark mark, int width) {
  const int x = width - static_cast<int>(kLegendInset), y = static_cast<int>(LegendRow(index));
  // The hollow square's left side is 1.5 px wide from x + 2.75; every other mark covers x + 7.
  return {x + (mark == LegendMark::kHollowSquare ? 3 : 7), y - 5};
}

std::vector<std::vector<Eigen::Vector3d>> ObstaclePolygons(const Scene& scene, const Model& model) {
  Box3 fabric;
  for (int k = 0; k < model.num_nodes; ++k) fabric.Add(Node(model, k));
  std::vector<Primitive> obstacles;
  const double floor_z = FloorHeight(scene.obstacles, fabric);
  AddObstacles(scene.obstacles, fabric, std::isnan(floor_z) ? fabric.min.z() : floor_z, &obstacles);
  std::vector<std::vector<Eigen::Vector3d>> polygons;
  for (const Primitive& primitive : obstacles) {
    if (primitive.points.size() >= 3) polygons.push_back(primitive.points);
  }
  return polygons;
}

void DrawDrapeView(const Scene& scene, const Model& model, std::ostream& png,
                   const DrapeViewOptions& options) {
  assert(model.num_nodes > 0);
  const bool front = model.dimension == 2;
  Camera camera = front ? Orient(-90.0, 0.0) : Orient(options.azimuth_deg, options.elevation_deg);
  Box3 fabric;
  for (int k = 0; k < model.num_nodes; ++k) fabric.Add(Node(model, k));

  std::vector<Primitive> primitives, floor;
  for (const auto& t : model.triangles) {
    primitives.push_back({{Node(model, t[0]), Node(model, t[1]), Node(model, t[2])}, {}, true});
  }
  for (const auto& e : model.edges) {
    primitives.push_back({{Node(model, e[0]), Node(model, e[1])}, kChain, true});
  }
  std::vector<Primitive> obstacles;
  const double floor_z = FloorHeight(scene.obstacles, fabric);
  AddObstacles(scene.obstacles, fabric, std::isnan(floor_z) ? fabric.min.z() : floor_z, &obstacles);
  const double edge = MeanEdgeLength(model);
  if (!front && !std::isnan(floor_z)) AddFloorShadow(model, floor_z, &floor);

  const double top = 75.0 + 20.0 * options.caption.size(), bottom = 60.0;
  std::vector<Primitive> framed = primitives;
  framed.insert(framed.end(), floor.begin(), floor.end());
  framed.insert(framed.end(), obstacles.begin(), obstacles.end());
  Frame(framed, fabric, options.width, options.height, top, bottom, &camera);

  SurfacePtr surface(cairo_image_surface_create(CAIRO_FORMAT_RGB24, options.width, options.height),
                     cairo_surface_destroy);
  ContextPtr context(cairo_create(surface.get()), cairo_destroy);
  cairo_t* cr = context.get();
  cairo_set_source_rgb(cr, 1, 1, 1);
  cairo_paint(cr);

  // Planes behind everything, then the floor shadow, then fabric and solid obstacles by depth.
  std::vector<Primitive> background;
  SplitObstacles(obstacles, edge, &background, &primitives);
  PaintPrimitives(cr, camera, &background, 0.0);
  PaintFloorShadow(cr, camera, floor);
  const double edge_px = edge * camera.scale;
  PaintPrimitives(cr, camera, &primitives, edge_px);
  PaintChainNodes(cr, camera, model, edge_px);
  PaintFixedNodes(cr, camera, model);

  Text(cr, 20, 30, scene.name, 18, true);
  std::string subtitle = std::to_string(model.num_nodes) + " nodes · ";
  subtitle += front ? "front view (x-z plane)"
                    : "orthographic view from azimuth " + Format("%g°", options.azimuth_deg) +
                          ", elevation " + Format("%g°", options.elevation_deg);
  Text(cr, 20, 50, subtitle, 13, false, {0.35, 0.35, 0.35});
  for (size_t k = 0; k < options.caption.size(); ++k) {
    Text(cr, 20, 70 + 20.0 * k, options.caption[k], 13);
  }
  PaintLegend(cr, scene, model, options.width);
  PaintAxes(cr, camera, 45, options.height - 35);
  ScaleBar(cr, options.width - 200, options.height - 25, camera.scale, 140);
  WritePng(surface.get(), png);
}

// ---- the top view of a drape --------------------------------------------------------------------

namespace {

// Pixels of a top-view point (x, y): x to the right, y up, centred on the profile's centre.
struct TopView {
  double cx, cy, scale;  // pixel centre, pixels per metre
  std::array<double, 2> centre;
  double X(double x) const { return cx + scale * (x - centre[0]); }
  double Y(double y) const { return cy - scale * (y - centre[1]); }
};

void ProfilePath(cairo_t* cr, const TopView& view, const RadialProfile& profile) {
  for (size_t k = 0; k < profile.radius.size(); ++k) {
    const double r = profile.radius[k], a = profile.theta[k];
    const double x = view.X(view.centre[0] + r * std::cos(a)),
                 y = view.Y(view.centre[1] + r * std::sin(a));
    if (k == 0)
      cairo_move_to(cr, x, y);
    else
      cairo_line_to(cr, x, y);
  }
  cairo_close_path(cr);
}

// Light circles around the centre every round radius, labelled along +x.
void PaintRings(cairo_t* cr, const TopView& view, double max_radius) {
  const double step = RoundLength(view.scale, 90.0);
  cairo_set_line_width(cr, 0.8);
  for (double r = step; r <= max_radius * 1.001; r += step) {
    cairo_set_source_rgb(cr, 0.85, 0.85, 0.85);
    cairo_arc(cr, view.cx, view.cy, r * view.scale, 0, 2 * M_PI);
    cairo_stroke(cr);
    Text(cr, view.cx + r * view.scale + 3, view.cy - 3, LengthLabel(r), 10, false, {0.6, 0.6, 0.6});
  }
  cairo_set_source_rgb(cr, 0.85, 0.85, 0.85);
  cairo_move_to(cr, view.cx - max_radius * view.scale, view.cy);
  cairo_line_to(cr, view.cx + max_radius * view.scale, view.cy);
  cairo_move_to(cr, view.cx, view.cy - max_radius * view.scale);
  cairo_line_to(cr, view.cx, view.cy + max_radius * view.scale);
  cairo_stroke(cr);
}

void PaintShadowUnion(cairo_t* cr, const TopView& view, const Model& model) {
  cairo_set_fill_rule(cr, CAIRO_FILL_RULE_WINDING);
  const SpecimenSurface surface = SurfaceAt(model, model.positions);
  const auto& p = surface.points;
  for (const auto& t : surface.triangles) {
    double x[3], y[3];
    for (int k = 0; k < 3; ++k) {
      x[k] = view.X(p[3 * t[k]]);
      y[k] = view.Y(p[3 * t[k] + 1]);
    }
    const double cross = (x[1] - x[0]) * (y[2] - y[0]) - (y[1] - y[0]) * (x[2] - x[0]);
    if (cross == 0.0) continue;
    const int second = cross > 0 ? 1 : 2, third = cross > 0 ? 2 : 1;
    cairo_move_to(cr, x[0], y[0]);
    cairo_line_to(cr, x[second], y[second]);
    cairo_line_to(cr, x[third], y[third]);
    cairo_close_path(cr);
  }
  cairo_set_source_rgba(cr, 0.20, 0.45, 0.80, 0.45);
  cairo_fill(cr);
}

// The disc, or without one the fixed nodes (the pin).
void PaintSupport(cairo_t* cr, const TopView& view, const Model& model, double disc_radius) {
  if (disc_radius > 0.0) {
    cairo_arc(cr, view.cx, view.cy, disc_radius * view.scale, 0, 2 * M_PI);
    cairo_set_source_rgba(cr, 0.30, 0.30, 0.30, 0.75);
    cairo_fill(cr);
    return;
  }
  cairo_set_source_rgb(cr, 0.2, 0.2, 0.2);
  for (int k = 0; k < model.num_nodes; ++k) {
    if (!(model.fixed[3 * k] || model.fixed[3 * k + 1] || model.fixed[3 * k + 2])) continue;
    cairo_arc(cr, view.X(model.positions[3 * k]), view.Y(model.positions[3 * k + 1]), 4, 0,
              2 * M_PI);
    cairo_fill(cr);
  }
}

// A red dot on the outline at each fold's crest.
void PaintFolds(cairo_t* cr, const TopView& view, const DrapeAnalysis& analysis) {
  const auto& radius = analysis.profile.radius;
  const int n = static_cast<int>(radius.size());
  for (double angle : analysis.folds.angles_deg) {
    const int k = static_cast<int>(std::lround(angle * n / 360.0)) % n;
    const double a = angle * M_PI / 180.0, r = radius[k];
    cairo_arc(cr, view.X(view.centre[0] + r * std::cos(a)),
              view.Y(view.centre[1] + r * std::sin(a)), 4.5, 0, 2 * M_PI);
    cairo_set_source_rgb(cr, 0.85, 0.1, 0.1);
    cairo_fill(cr);
  }
}

// Swatch and label of the legend, from (x, y) to the right; returns the x after it.
double LegendEntry(cairo_t* cr, double x, double y, const std::string& label, int kind) {
  switch (kind) {
    case 0:  // dashed outline
      cairo_set_source_rgb(cr, 0.25, 0.25, 0.25);
      cairo_set_line_width(cr, 1.5);
      cairo_set_dash(cr, kDash, 2, 0);
      cairo_move_to(cr, x, y - 4);
      cairo_line_to(cr, x + 24, y - 4);
      cairo_stroke(cr);
      cairo_set_dash(cr, nullptr, 0, 0);
      break;
    case 1:  // shadow
      cairo_rectangle(cr, x, y - 10, 24, 12);
      cairo_set_source_rgba(cr, 0.20, 0.45, 0.80, 0.45);
      cairo_fill_preserve(cr);
      cairo_set_source_rgb(cr, 0.08, 0.22, 0.5);
      cairo_set_line_width(cr, 1.2);
      cairo_stroke(cr);
      break;
    case 2:  // disc
      cairo_rectangle(cr, x, y - 10, 24, 12);
      cairo_set_source_rgba(cr, 0.30, 0.30, 0.30, 0.75);
      cairo_fill(cr);
      break;
    case 3:  // pin (fixed nodes)
      cairo_arc(cr, x + 12, y - 4, 4, 0, 2 * M_PI);
      cairo_set_source_rgb(cr, 0.2, 0.2, 0.2);
      cairo_fill(cr);
      break;
    default:  // fold crest
      cairo_arc(cr, x + 12, y - 4, 4.5, 0, 2 * M_PI);
      cairo_set_source_rgb(cr, 0.85, 0.1, 0.1);
      cairo_fill(cr);
  }
  Text(cr, x + 30, y, label, 12);
  return x + 30 + TextWidth(cr, label, 12) + 22;
}

std::string Centimetres(double metres) { return Format("%.1f", 100.0 * metres); }

}  // namespace

std::string CoefficientText(double value) {
  return Format(std::abs(value) >= 1e-3 || value == 0.0 ? "%.3f" : "%.2g", value);
}

void DrawShadowView(const Scene& scene, const Model& model, const DrapeAnalysis& analysis,
                    std::ostream& png, const ShadowViewOptions& options) {
  const int size = options.size;
  const double top = 100.0, bottom = 70.0;
  const auto& draped = analysis.profile.radius;
  const auto& flat = analysis.flat_profile.radius;
  double reach = analysis.disc_radius;
  for (double r : draped) reach = std::max(reach, r);
  for (double r : flat) reach = std::max(reach, r);
  if (!(reach > 0.0)) reach = 1.0;
  const double half = 0.5 * std::min(size - 40.0, size - top - bottom);
  const TopView view{0.5 * size, top + 0.5 * (size - top - bottom), half / (1.04 * reach),
                     analysis.profile.centre};

  SurfacePtr surface(cairo_image_surface_create(CAIRO_FORMAT_RGB24, size, size),
                     cairo_surface_destroy);
  ContextPtr context(cairo_create(surface.get()), cairo_destroy);
  cairo_t* cr = context.get();
  cairo_set_source_rgb(cr, 1, 1, 1);
  cairo_paint(cr);

  PaintRings(cr, view, reach);
  PaintShadowUnion(cr, view, model);
  ProfilePath(cr, view, analysis.profile);
  cairo_set_source_rgb(cr, 0.08, 0.22, 0.5);
  cairo_set_line_width(cr, 1.5);
  cairo_stroke(cr);
  PaintSupport(cr, view, model, analysis.disc_radius);
  ProfilePath(cr, view, analysis.flat_profile);
  cairo_set_source_rgb(cr, 0.25, 0.25, 0.25);
  cairo_set_dash(cr, kDash, 2, 0);
  cairo_stroke(cr);
  cairo_set_dash(cr, nullptr, 0, 0);
  PaintFolds(cr, view, analysis);

  const DrapeCoefficient& dc = analysis.coefficient;
  const Folds& folds = analysis.folds;
  Text(cr, 20, 30, scene.name + " — top view", 18, true);
  std::string line = "Drape coefficient: ";
  if (analysis.disc_radius > 0.0) {
    const std::string bar = options.drape_coefficient_error
                                ? " ± " + RoundedNumber(*options.drape_coefficient_error, 2)
                                : "";
    line += "Cusick " + CoefficientText(dc.cusick) + bar +
            "  (A_shadow − A_disc)/(A_specimen − A_disc);  ";
  }
  line += "ratio " + CoefficientText(dc.ratio) + "  (A_shadow/A_flat)";
  Text(cr, 20, 55, line, 13);
  Text(cr, 20, 77,
       "Folds: " + std::to_string(folds.count) +
           "     shadow radius min / mean / max: " + Centimetres(analysis.radius_min) + " / " +
           Centimetres(analysis.radius_mean) + " / " + Centimetres(analysis.radius_max) + " cm",
       13);
  double x = 20;
  x = LegendEntry(cr, x, size - 20, "flat specimen", 0);
  x = LegendEntry(cr, x, size - 20, "shadow", 1);
  x = analysis.disc_radius > 0.0 ? LegendEntry(cr, x, size - 20, "disc", 2)
                                 : LegendEntry(cr, x, size - 20, "fixed node (pin)", 3);
  LegendEntry(cr, x, size - 20, "fold crest", 4);
  ScaleBar(cr, size - 140, size - 45, view.scale, 100);
  Text(cr, size - 140, size - 18, "seen from above", 11, false, {0.4, 0.4, 0.4});
  WritePng(surface.get(), png);
}

}  // namespace drape
