#include "reference/reference.hpp"

#include <airlight/error.hpp>
#include <algorithm>
#include <atomic>
#include <cmath>
#include <glm/common.hpp>
#include <glm/exponential.hpp>
#include <glm/geometric.hpp>
#include <limits>
#include <numbers>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "core/progress.hpp"
#include "geometry/camera.hpp"
#include "optics/airlight.hpp"
#include "optics/light.hpp"
#include "optics/media.hpp"
#include "reference/ray_caster.hpp"

namespace airlight::reference {
namespace {

constexpr int tile_size = 16;
constexpr double infinity = std::numeric_limits<double>::infinity();
// Shadow rays to a point or spot light stop this fraction of the distance short of
// it, so that a surface the light sits on (a lamp on a ceiling) does not block it.
constexpr double light_clearance = 1e-5;

// Shadow rays leave a surface point p from this far along its geometric normal, so
// that the surface does not shadow itself: Embree works in float, so a hit point is
// uncertain by a few ulps of its coordinates; 1e-4 of the coordinate scale is far
// above that and far below any feature of the scenes. (Points on view rays in the
// medium need no offset: a sample that float rounding puts behind the surface at d
// is at most ulps away, so it can only darken a stretch of that length.)
double surface_offset(const glm::dvec3& p) {
  const glm::dvec3 a = glm::abs(p);
  return 1e-4 * std::max({1.0, a.x, a.y, a.z});
}

// Per-tile counters, added to the frame's once per tile.
struct Counters {
  long shadow_rays = 0;
  long nonfinite = 0;
};

// The straight path from x to a light: unit direction and length (∞ for directional).
struct LightPath {
  glm::dvec3 dir{0.0};
  double distance = 0.0;
};

LightPath path_to_light(const Light& light, const glm::dvec3& x) {
  if (light.type == LightType::directional) return {-glm::normalize(glm::dvec3(light.direction)), infinity};
  const glm::dvec3 to_light = glm::dvec3(light.position) - x;
  const double distance = glm::length(to_light);
  return {distance > 0.0 ? to_light / distance : glm::dvec3(0.0), distance};
}

// What one frame's pixels share: the scene, its ray caster, the settings.
struct Context {
  const Scene& scene;
  const RayCaster& rays;
  const Settings& settings;

  // V: does light reach `origin`? An occlusion ray from origin toward the light.
  bool visible(const Light& light, const glm::dvec3& origin, Counters& count) const {
    const LightPath path = path_to_light(light, origin);
    if (path.distance == 0.0) return true;  // at the light itself: nothing between
    ++count.shadow_rays;
    return !rays.occluded(origin, path.dir, 0.0, path.distance * (1.0 - light_clearance));
  }
};

// A shaded surface point: normals flipped toward the viewer (docs/design.md §1, Lambertian).
struct SurfacePoint {
  glm::dvec3 position{0.0};
  glm::dvec3 geometric_normal{0.0};
  glm::dvec3 shading_normal{0.0};  // interpolated vertex normal
  glm::dvec3 albedo{0.0};
};

glm::dvec3 facing(const glm::dvec3& n, const glm::dvec3& view_dir) {
  return glm::dot(n, view_dir) > 0.0 ? -n : n;
}

// The vertex normals interpolated at Embree's barycentrics (u, v); the geometric
// normal when the mesh has none or they cancel.
glm::dvec3 interpolated_normal(const Mesh& mesh, const Hit& hit) {
  if (mesh.normals.size() != mesh.positions.size()) return hit.geometric_normal;
  const glm::uvec3 tri = mesh.triangles[hit.triangle];
  const glm::dvec3 n = (1.0 - hit.u - hit.v) * glm::dvec3(mesh.normals[tri.x]) +
                       hit.u * glm::dvec3(mesh.normals[tri.y]) + hit.v * glm::dvec3(mesh.normals[tri.z]);
  const double length = glm::length(n);
  return length > 0.0 ? n / length : hit.geometric_normal;
}

SurfacePoint surface_point(const Scene& scene, const optics::Ray& ray, const Hit& hit) {
  const Mesh& mesh = scene.meshes[hit.mesh];
  return {ray.origin + hit.t * ray.dir, facing(hit.geometric_normal, ray.dir),
          facing(interpolated_normal(mesh, hit), ray.dir), glm::dvec3(mesh.albedo)};
}

// Irradiance from one light at a surface point: E·cos θ_i·V·exp(−τ_light) (docs/design.md §1).
// A light behind the triangle's own plane is blocked by the triangle.
glm::dvec3 irradiance(const Context& c, const Light& light, const SurfacePoint& s, Counters& count) {
  const optics::Arrival arrival = optics::arrival(light, c.scene.light_model, s.position);
  const double cos_i = glm::dot(s.shading_normal, arrival.to_light);
  const bool lit = cos_i > 0.0 && glm::dot(s.geometric_normal, arrival.to_light) > 0.0 &&
                   arrival.irradiance != glm::dvec3(0.0);
  if (!lit) return glm::dvec3(0.0);
  const glm::dvec3 origin = s.position + surface_offset(s.position) * s.geometric_normal;
  if (!c.visible(light, origin, count)) return glm::dvec3(0.0);
  return arrival.irradiance * cos_i * glm::exp(-optics::light_leg_depth(c.scene, light, s.position));
}

// L_surf = albedo·ambient + Σ_lights albedo/π · irradiance (docs/design.md §1).
glm::dvec3 surface_radiance(const Context& c, const SurfacePoint& s, Counters& count) {
  glm::dvec3 e(0.0);
  for (const Light& light : c.scene.lights) e += irradiance(c, light, s, count);
  return s.albedo * (glm::dvec3(c.scene.ambient) + e * std::numbers::inv_pi);
}

// T(d) between the eye and a surface point; 1 under the simplified model (Nilsson 2.5).
glm::dvec3 eye_transmittance(const Scene& scene, const glm::dvec3& eye, const glm::dvec3& p) {
  return glm::exp(-optics::eye_leg_depth(scene, eye, p));
}

// L_air = Σ_lights ∫_0^d V·e dx with V by Embree occlusion rays (docs/design.md §1).
glm::dvec3 airlight(const Context& c, const optics::Ray& ray, double d, Counters& count) {
  const optics::QuadratureSettings quadrature{.rel_tol = c.settings.rel_tol,
                                              .min_segments = c.settings.min_segments};
  glm::dvec3 sum(0.0);
  for (const Light& light : c.scene.lights) {
    const optics::Visibility visible = [&](const glm::dvec3& x) {
      return c.visible(light, x, count);
    };
    sum += optics::airlight_quadrature(c.scene, light, ray, 0.0, d, visible, quadrature);
  }
  return sum;
}

struct Radiance {
  glm::dvec3 surface{0.0};  // L_surf · T(d)
  glm::dvec3 airlight{0.0};
};

// One view ray: the first surface at view depth >= near (moved by near_shift), else the far plane.
Radiance trace(const Context& c, const optics::Ray& ray, Counters& count) {
  const Camera& camera = c.scene.camera;
  const double far = geometry::far_distance(camera, ray.dir);
  const double near = std::max(geometry::near_distance(camera, ray.dir) + c.settings.near_shift, 0.0);
  const std::optional<Hit> hit = c.rays.intersect(ray, near, far);
  Radiance radiance;
  if (hit) {
    const SurfacePoint s = surface_point(c.scene, ray, *hit);
    radiance.surface = surface_radiance(c, s, count) * eye_transmittance(c.scene, ray.origin, s.position);
  }
  if (c.settings.airlight) radiance.airlight = airlight(c, ray, hit ? hit->t : far, count);
  return radiance;
}

// Double to float pixel; counts and replaces what a float image cannot hold.
glm::vec3 to_pixel(const glm::dvec3& value, Counters& count) {
  constexpr double float_max = std::numeric_limits<float>::max();
  glm::vec3 pixel;
  for (int k = 0; k < 3; ++k) {
    const double v = value[k];
    const bool representable = std::isfinite(v) && std::abs(v) <= float_max;
    if (!representable) ++count.nonfinite;
    pixel[k] = static_cast<float>(std::isnan(v) ? 0.0 : std::clamp(v, -float_max, float_max));
  }
  return pixel;
}

struct TileGrid {
  int width, height, columns, rows;
  TileGrid(int w, int h)
      : width(w), height(h), columns((w + tile_size - 1) / tile_size), rows((h + tile_size - 1) / tile_size) {}
  int count() const { return columns * rows; }
};

void render_tile(const Context& c, const TileGrid& grid, int tile, Images& frame, Counters& count) {
  const int x0 = tile % grid.columns * tile_size, y0 = tile / grid.columns * tile_size;
  for (int j = y0; j < std::min(y0 + tile_size, grid.height); ++j)
    for (int i = x0; i < std::min(x0 + tile_size, grid.width); ++i) {
      if (!c.settings.pixels.empty() && !c.settings.pixels[static_cast<size_t>(j * grid.width + i)]) continue;
      const optics::Ray ray = geometry::primary_ray(c.scene.camera, grid.width, grid.height, i + c.settings.subpixel.x,
                                                          j + c.settings.subpixel.y);
      const Radiance radiance = trace(c, ray, count);
      frame.surface.at(i, j) = to_pixel(radiance.surface, count);
      frame.airlight.at(i, j) = to_pixel(radiance.airlight, count);
      frame.composite.at(i, j) = to_pixel(radiance.surface + radiance.airlight, count);
    }
}

}  // namespace

Images render(const Scene& scene, int width, int height, const Settings& settings, Control* control) {
  if (width <= 0 || height <= 0) throw Failure("reference: the image size must be positive");
  if (!settings.pixels.empty() && settings.pixels.size() != static_cast<size_t>(width) * height)
    throw Failure("reference: the pixels to render do not match the image's size");
  const RayCaster rays(scene);
  const Context context{scene, rays, settings};
  const TileGrid grid(width, height);
  Images frame{Image(width, height), Image(width, height), Image(width, height)};
  std::atomic<long> shadow_rays{0}, nonfinite{0};
  Progress progress("reference", grid.count());
  if (control) control->total = grid.count();
  tbb::parallel_for(tbb::blocked_range<int>(0, grid.count(), 1), [&](const tbb::blocked_range<int>& tiles) {
    for (int tile = tiles.begin(); tile != tiles.end(); ++tile) {
      if (control && control->cancel) return;
      Counters count;
      render_tile(context, grid, tile, frame, count);
      shadow_rays += count.shadow_rays;
      nonfinite += count.nonfinite;
      progress.advance();
      if (control) ++control->done;
    }
  });
  if (control && control->cancel) throw Cancelled();
  frame.shadow_rays = shadow_rays;
  frame.nonfinite = nonfinite;
  return frame;
}

}  // namespace airlight::reference
