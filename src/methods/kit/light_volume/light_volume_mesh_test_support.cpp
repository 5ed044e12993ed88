#include "methods/kit/light_volume/light_volume_mesh_test_support.hpp"

#include "geometry/camera.hpp"
#include "gpu/program.hpp"
#include "methods/kit/testing/test_support.hpp"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstring>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <unordered_map>

namespace airlight::kit::volume_test {
namespace {

// A tilted base, boxes nearer the light, and boxes with no occluder.
std::vector<Rect> random_rects(std::mt19937& rng, int count, double near_lo, double near_hi, int none) {
  std::uniform_real_distribution<double> u(-1.0, 1.0), v(near_lo, near_hi), size(0.1, 0.6);
  std::vector<Rect> rects;
  for (int k = 0; k < count + none; ++k) {
    const double x = u(rng), y = u(rng), w = size(rng), h = size(rng);
    rects.push_back({x - w / 2, y - h / 2, x + w / 2, y + h / 2, k < count ? v(rng) : -1.0});
  }
  return rects;
}

// The last of the boxes holding (x, y), or the base.
double map_value(const std::vector<Rect>& rects, double base, double x, double y) {
  double value = base;
  for (const Rect& r : rects)
    if (x >= r.x0 && x < r.x1 && y >= r.y0 && y < r.y1) value = r.value;  // later boxes cover earlier ones
  return value;
}

}  // namespace

Rig::Rig(Kind k, int s, unsigned seed) : kind(k), size(s) {
  std::mt19937 rng(seed);
  scene.name = "light_volume";
  scene.camera.position = {3.0f, 4.0f, 12.0f};
  scene.camera.look_at = {0.0f, 1.0f, 0.0f};
  scene.camera.far = 30.0f;
  scene.medium.sigma_s = Color(0.05f);
  scene.meshes.push_back(test::box({-1, 0, -1}, {1, 1, 1}, Color(0.5f)));
  if (kind == Kind::spot) {
    scene.lights.push_back(test::make_light(LightType::spot, {0, 10, 0}, {0, -1, 0}, 100.0f, 30.0f));
    const glm::dvec3 l(0, 10, 0);
    shadow.view = glm::mat4(glm::lookAt(l, l + glm::dvec3(0, -1, 0), glm::dvec3(0, 0, 1)));
    shadow.projection = glm::mat4(glm::perspective(glm::radians(70.0), 1.0, 0.5, 40.0));
    upload_2d(random_rects(rng, 10, 3.0, 8.0, 3), 9.0);
  } else if (kind == Kind::directional) {
    const glm::dvec3 dir = glm::normalize(glm::dvec3(0.2, -1.0, 0.1));
    scene.lights.push_back(test::make_light(LightType::directional, {}, glm::vec3(dir), 1.0f));
    shadow.view = glm::mat4(glm::lookAt(-20.0 * dir, glm::dvec3(0.0), glm::dvec3(0, 0, 1)));
    shadow.projection = glm::mat4(glm::ortho(-10.0, 10.0, -10.0, 10.0, 1.0, 40.0));
    upload_2d(random_rects(rng, 10, 8.0, 18.0, 3), 20.0);
  } else {
    scene.lights.push_back(test::make_light(LightType::point, {0, 3, 0}, {0, -1, 0}, 100.0f));
    upload_cube(rng);
  }
  shadow.texture = texture.id();
  frame.prepare(scene);
}

void Rig::upload_2d(const std::vector<Rect>& rects, double base) {
  matrix = glm::dmat4(shadow.projection) * glm::dmat4(shadow.view);
  const glm::dmat4 p(shadow.projection);
  std::vector<float> depth(static_cast<size_t>(size) * size);
  for (int j = 0; j < size; ++j)
    for (int i = 0; i < size; ++i) {
      const double x = 2.0 * (i + 0.5) / size - 1.0, y = 2.0 * (j + 0.5) / size - 1.0;
      const double v = map_value(rects, base + 2.0 * x + 1.0 * y, x, y);
      const glm::dvec4 clip = p * glm::dvec4(0.0, 0.0, -v, 1.0);
      depth[static_cast<size_t>(j) * size + i] = v < 0.0 ? 1.0f : static_cast<float>(0.5 * clip.z / clip.w + 0.5);
    }
  texture = gpu::make_texture(GL_TEXTURE_2D, GL_DEPTH_COMPONENT32F, size, size);
  glTextureSubImage2D(texture.id(), 0, 0, 0, size, size, GL_DEPTH_COMPONENT, GL_FLOAT, depth.data());
  shadow.kind = EngineShadow::Kind::map;
}

void Rig::upload_cube(std::mt19937& rng) {
  texture = gpu::make_texture(GL_TEXTURE_CUBE_MAP, GL_R32F, size, size);
  std::vector<float> distance(static_cast<size_t>(size) * size);
  for (int face = 0; face < 6; ++face) {
    const std::vector<Rect> rects = random_rects(rng, 5, 1.0, 4.0, 1);
    const double base = 6.0 + 0.5 * face;
    for (int j = 0; j < size; ++j)
      for (int i = 0; i < size; ++i) {
        const double s = 2.0 * (i + 0.5) / size - 1.0, t = 2.0 * (j + 0.5) / size - 1.0;
        const double d = map_value(rects, base + s - 0.5 * t, s, t);
        distance[static_cast<size_t>(j) * size + i] = d < 0.0 ? FLT_MAX : static_cast<float>(d);
      }
    glTextureSubImage3D(texture.id(), 0, 0, 0, face, size, size, 1, GL_RED, GL_FLOAT, distance.data());
  }
  shadow.kind = EngineShadow::Kind::cube;
  shadow.stores = EngineShadow::Stores::distance;
}

void Rig::render(const glm::vec3& eye) {
  scene.camera.position = eye;
  scene.camera.look_at = eye + glm::vec3(0.3f, -0.2f, -1.0f);
  EngineFrame engine;
  engine.shadows = {shadow};
  PassTimer timer;
  frame.render(frame_inputs(scene, width, height), FrameSettings{size, 1.0f}, &engine, {true, false}, timer);
  frame.bind();
  const bool cube = kind == Kind::point;
  GLint id = 0;
  glActiveTexture(GL_TEXTURE0 + (cube ? binding::shadow_cubes : binding::shadow_maps));
  glGetIntegerv(cube ? GL_TEXTURE_BINDING_CUBE_MAP_ARRAY : GL_TEXTURE_BINDING_2D_ARRAY, &id);
  glActiveTexture(GL_TEXTURE0);
  stored.assign(static_cast<size_t>(size) * size * (cube ? 6 : 1), 0.0f);
  glGetTextureImage(static_cast<GLuint>(id), 0, GL_RED, GL_FLOAT, static_cast<GLsizei>(stored.size() * sizeof(float)),
                    stored.data());
}

double Rig::reach() const {
  return geometry::corner_distance(scene.camera, double(width) / height, scene.camera.far);
}

glm::dvec3 Rig::direction() const { return glm::dvec3(glm::normalize(light().direction)); }

float Rig::far_depth() const {
  if (kind == Kind::directional) return static_cast<float>(glm::dot(eye(), direction()) + 2.0 * reach());
  return static_cast<float>(2.0 * (glm::length(eye() - glm::dvec3(light().position)) + reach()));
}

float Rig::cap_depth() const { return static_cast<float>(glm::dot(eye(), direction()) - 2.0 * reach()); }

double Rig::clamped(double v) const {
  const double lo = kind == Kind::directional ? cap_depth() : 0.0;
  return std::min(std::max(v, lo), static_cast<double>(far_depth()));
}

double Rig::texel(int face, int i, int j) const {
  return clamped(stored[(static_cast<size_t>(face) * size + j) * size + i]);
}

glm::dvec3 Rig::point_2d(double x, double y, double d) const {
  const glm::dmat4 inverse = glm::inverse(matrix);
  const glm::dvec4 a = inverse * glm::dvec4(x, y, -1.0, 1.0), b = inverse * glm::dvec4(x, y, 1.0, 1.0);
  const glm::dvec3 near(a / a.w), far_point(b / b.w);
  const glm::dvec3 along = glm::normalize(far_point - near);
  if (kind == Kind::spot) return glm::dvec3(light().position) + d * along;
  return near + (d - glm::dot(near, direction())) / glm::dot(along, direction()) * along;
}

std::pair<int, double> Lines::line(const glm::dvec3& p) {
  if (!directional && p == light) return {-1, 0.0};
  const glm::dvec3 key = directional ? p - glm::dot(p, travel) * travel : glm::normalize(p - light);
  const double along = directional ? glm::dot(p, travel) : glm::length(p - light);
  const std::array<long long, 3> cell = {std::llround(key.x / tolerance), std::llround(key.y / tolerance),
                                         std::llround(key.z / tolerance)};
  for (long long dz = -1; dz <= 1; ++dz)
    for (long long dy = -1; dy <= 1; ++dy)
      for (long long dx = -1; dx <= 1; ++dx) {
        const auto it = cells.find({cell[0] + dx, cell[1] + dy, cell[2] + dz});
        if (it != cells.end()) return {it->second, along};
      }
  cells.emplace(cell, count);
  return {count++, along};
}

std::vector<Triangle> triangles(const std::vector<CountedTriangle>& records) {
  std::vector<Triangle> t;
  for (const CountedTriangle& r : records)
    t.push_back({glm::dvec3(r.corners[0]), glm::dvec3(r.corners[1]), glm::dvec3(r.corners[2])});
  return t;
}

Closure closure(const std::vector<CountedTriangle>& records, Lines lines) {
  std::unordered_map<std::string, uint32_t> ids;
  auto id = [&](const glm::vec4& p) {
    std::string key(12, '\0');
    std::memcpy(key.data(), &p, 12);
    return ids.emplace(key, static_cast<uint32_t>(ids.size())).first->second;
  };
  std::unordered_map<uint64_t, int> half_edges;
  std::map<int, std::vector<std::pair<double, double>>> stretches;  // per line: (from, to) along it
  Closure c;
  for (const CountedTriangle& r : records) {
    const uint32_t v[3] = {id(r.corners[0]), id(r.corners[1]), id(r.corners[2])};
    if (v[0] == v[1] || v[1] == v[2] || v[0] == v[2]) {
      ++c.degenerate;
      continue;
    }
    for (int k = 0; k < 3; ++k) {
      const auto [la, a] = lines.line(glm::dvec3(r.corners[k]));
      const auto [lb, b] = lines.line(glm::dvec3(r.corners[(k + 1) % 3]));
      if (la == lb || la < 0 || lb < 0) stretches[std::max(la, lb)].push_back({a, b});
      else ++half_edges[(uint64_t(v[k]) << 32) | v[(k + 1) % 3]];
    }
  }
  for (const auto& [line, along] : stretches) {
    std::vector<double> ends;
    for (const auto& [a, b] : along) ends.insert(ends.end(), {a, b});
    std::sort(ends.begin(), ends.end());
    ends.erase(std::unique(ends.begin(), ends.end()), ends.end());
    std::vector<int> change(ends.size() + 1, 0);
    for (const auto& [a, b] : along) {
      const auto at = [&](double x) { return std::lower_bound(ends.begin(), ends.end(), x) - ends.begin(); };
      ++change[static_cast<size_t>(at(a))];
      --change[static_cast<size_t>(at(b))];
    }
    int covered = 0;
    for (const int step : change) c.uncancelled_stretches += (covered += step) != 0;
  }
  for (const auto& [key, count] : half_edges) {
    const uint64_t reverse = (key << 32) | (key >> 32);
    const auto it = half_edges.find(reverse);
    const int back = it == half_edges.end() ? 0 : it->second;
    if (count == 1 && back == 1) continue;
    if (count + back == 1) ++c.boundary;
    else if (back == 0) ++c.inconsistent;
    else ++c.other;
  }
  c.vertices = ids.size();
  return c;
}

Lines lines_of(const Light& light) {
  const bool directional = light.type == LightType::directional;
  return {glm::dvec3(light.position), glm::normalize(glm::dvec3(light.direction)), directional, directional ? 1e-4 : 1e-5,
          {}, 0};
}

double signed_volume(const std::vector<Triangle>& mesh, const glm::dvec3& origin) {
  double v = 0.0;
  for (const Triangle& t : mesh) v += glm::dot(t.a - origin, glm::cross(t.b - origin, t.c - origin));
  return v / 6.0;
}

bool inside(const std::vector<Triangle>& mesh, const glm::dvec3& x, const glm::dvec3& dir) {
  int crossings = 0;
  for (const Triangle& t : mesh) {
    const glm::dvec3 e1 = t.b - t.a, e2 = t.c - t.a, p = glm::cross(dir, e2);
    const double det = glm::dot(e1, p);
    if (det == 0.0) continue;
    const glm::dvec3 s = x - t.a;
    const double u = glm::dot(s, p) / det;
    if (u < 0.0 || u > 1.0) continue;
    const glm::dvec3 q = glm::cross(s, e1);
    const double v = glm::dot(dir, q) / det;
    if (v < 0.0 || u + v > 1.0) continue;
    if (glm::dot(e2, q) / det > 0.0) ++crossings;
  }
  return crossings % 2 == 1;
}

glm::dvec3 random_direction(std::mt19937& rng) {
  std::normal_distribution<double> n;
  return glm::normalize(glm::dvec3(n(rng), n(rng), n(rng)));
}

int parity(const std::vector<Triangle>& mesh, const glm::dvec3& x, std::mt19937& rng) {
  const bool a = inside(mesh, x, random_direction(rng)), b = inside(mesh, x, random_direction(rng));
  return a == b ? (a ? 1 : 0) : -1;
}

std::unique_ptr<LightVolumeMesh> built(Rig& rig, int resolution, Depth depth) {
  auto mesh = std::make_unique<LightVolumeMesh>(resolution, depth);
  mesh->prepare(rig.scene);
  PassTimer timer;
  mesh->build(rig.frame, timer);
  return mesh;
}

bool well_formed(const CountedTriangle& t) {
  const glm::vec3 n(t.plane), a(t.corners[0]), b(t.corners[1]), c(t.corners[2]);
  if (t.light_weight != glm::ivec4(0, 1, 0, 0)) return false;
  if (n == glm::vec3(0.0f)) return a == b || b == c || c == a;
  return std::abs(glm::length(n) - 1.0f) < 1e-5f;
}

}  // namespace airlight::kit::volume_test
