#include "scene/shapes.hpp"

#include "scene/mesh_build.hpp"

#include <cmath>
#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>
#include <glm/mat3x3.hpp>

namespace airlight::scene_mesh {
namespace {

// A point on the unit circle in the xz plane; increasing angle turns
// counter-clockwise seen from +y, so (ring j, ring j+1, up) winds outward.
glm::vec3 circle(int j, int segments) {
  const float phi = glm::two_pi<float>() * static_cast<float>(j % segments) / segments;
  return {std::cos(phi), 0.0f, -std::sin(phi)};
}

// One ring of vertices, normal(dir) giving each vertex's normal from its
// direction off the axis; returns the index of the first.
template <class NormalOf>
uint32_t ring(MeshBuilder& b, const glm::vec3& center, float radius, int segments,
              NormalOf normal) {
  const uint32_t first = static_cast<uint32_t>(b.mesh().positions.size());
  for (int j = 0; j < segments; ++j) {
    const glm::vec3 dir = circle(j, segments);
    b.vertex(center + radius * dir, normal(dir));
  }
  return first;
}

// Quads between two rings of `segments` vertices (lower below upper).
void band(MeshBuilder& b, uint32_t lower, uint32_t upper, int segments) {
  for (int j = 0; j < segments; ++j) {
    const uint32_t k = static_cast<uint32_t>(j), k1 = static_cast<uint32_t>((j + 1) % segments);
    b.quad(lower + k, lower + k1, upper + k1, upper + k);
  }
}

// A triangle fan from a ring to one apex vertex; `up` when the apex is above.
void fan(MeshBuilder& b, uint32_t ring_start, uint32_t apex, int segments, bool up) {
  for (int j = 0; j < segments; ++j) {
    const uint32_t k = ring_start + static_cast<uint32_t>(j);
    const uint32_t k1 = ring_start + static_cast<uint32_t>((j + 1) % segments);
    if (up) b.triangle(k, k1, apex);
    else b.triangle(apex, k1, k);
  }
}

// The rotation taking +y to n by the shortest arc (a half turn about x for -y).
// In double: near -y the formula divides by a small 1 + cos.
glm::mat3 rotation_from_y(const glm::vec3& n) {
  const glm::dvec3 y(0, 1, 0), d = glm::normalize(glm::dvec3(n));
  const double c = glm::dot(y, d);
  if (c < -1.0 + 1e-9) return glm::mat3(1, 0, 0, 0, -1, 0, 0, 0, -1);
  // Rodrigues with axis·sin = y × n, and 1 − cos = sin² / (1 + cos).
  const glm::dvec3 v = glm::cross(y, d);
  const glm::dmat3 vx(0, v.z, -v.y, -v.z, 0, v.x, v.y, -v.x, 0);  // column-major [v]×
  return glm::mat3(glm::dmat3(1.0) + vx + vx * vx * (1.0 / (1.0 + c)));
}

}  // namespace

Mesh make_box(const glm::vec3& min, const glm::vec3& max) {
  MeshBuilder b;
  for (int axis = 0; axis < 3; ++axis) {
    const int u = (axis + 1) % 3, v = (axis + 2) % 3;  // u × v = axis
    for (const float side : {-1.0f, 1.0f}) {
      glm::vec3 normal(0.0f);
      normal[axis] = side;
      glm::vec3 corner[4];
      const float uv[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};  // counter-clockwise about +axis
      for (int c = 0; c < 4; ++c) {
        corner[c][axis] = side > 0 ? max[axis] : min[axis];
        corner[c][u] = uv[c][0] > 0 ? max[u] : min[u];
        corner[c][v] = uv[c][1] > 0 ? max[v] : min[v];
      }
      uint32_t i[4];
      for (int c = 0; c < 4; ++c) i[c] = b.vertex(corner[c], normal);
      if (side > 0) b.quad(i[0], i[1], i[2], i[3]);
      else b.quad(i[3], i[2], i[1], i[0]);
    }
  }
  return b.take("box");
}

Mesh make_sphere(const glm::vec3& center, float radius, int segments) {
  MeshBuilder b;
  const int rings = std::max(2, segments / 2);
  const uint32_t north = b.vertex(center + glm::vec3(0, radius, 0), {0, 1, 0});
  uint32_t upper = 0;
  for (int k = 1; k < rings; ++k) {
    const float theta = glm::pi<float>() * static_cast<float>(k) / rings;
    const float y = std::cos(theta);
    const float s = std::sin(theta);
    const uint32_t lower = ring(b, center + glm::vec3(0, radius * y, 0), radius * s, segments,
                                [&](glm::vec3 dir) { return dir * s + glm::vec3(0, y, 0); });
    if (k == 1) fan(b, lower, north, segments, true);
    else band(b, lower, upper, segments);
    upper = lower;
  }
  const uint32_t south = b.vertex(center - glm::vec3(0, radius, 0), {0, -1, 0});
  fan(b, upper, south, segments, false);
  return b.take("sphere");
}

Mesh make_plane(const glm::vec3& center, glm::vec2 size, const glm::vec3& normal) {
  const glm::mat3 r = rotation_from_y(normal);
  const glm::vec3 ex = r[0] * (0.5f * size.x), ez = r[2] * (0.5f * size.y);
  MeshBuilder b;
  const uint32_t a = b.vertex(center - ex - ez, normal), c = b.vertex(center - ex + ez, normal);
  const uint32_t d = b.vertex(center + ex + ez, normal), e = b.vertex(center + ex - ez, normal);
  b.quad(a, c, d, e);  // counter-clockwise about +normal, since z × x = y
  return b.take("plane");
}

Mesh make_cylinder(const glm::vec3& base, float radius, float height, int segments) {
  MeshBuilder b;
  const glm::vec3 top = base + glm::vec3(0, height, 0);
  const auto radial = [](glm::vec3 dir) { return dir; };
  const auto down = [](glm::vec3) { return glm::vec3(0, -1, 0); };
  const auto up = [](glm::vec3) { return glm::vec3(0, 1, 0); };
  const uint32_t side_bottom = ring(b, base, radius, segments, radial);
  const uint32_t side_top = ring(b, top, radius, segments, radial);
  band(b, side_bottom, side_top, segments);
  const uint32_t cap_bottom = ring(b, base, radius, segments, down);
  fan(b, cap_bottom, b.vertex(base, {0, -1, 0}), segments, false);
  const uint32_t cap_top = ring(b, top, radius, segments, up);
  fan(b, cap_top, b.vertex(top, {0, 1, 0}), segments, true);
  return b.take("cylinder");
}

Mesh make_arch(const glm::vec3& center, float inner_radius, float outer_radius, float depth,
               int segments) {
  MeshBuilder b;
  // Direction j of the half circle, exact at the ends so that they lie on y = center.y.
  const auto dir = [&](int j) -> glm::vec3 {
    if (j == 0 || j == segments) return {j == 0 ? 1.0f : -1.0f, 0.0f, 0.0f};
    const float phi = glm::pi<float>() * static_cast<float>(j) / segments;
    return {std::cos(phi), std::sin(phi), 0.0f};
  };
  const float h = 0.5f * depth, ri = inner_radius, ro = outer_radius;
  const auto at = [&](int j, float r, float z) { return center + r * dir(j) + glm::vec3(0, 0, z); };
  // A face swept along the arch: quads (p_j, q_j, q_j+1, p_j+1) between the
  // points at (radius, z) `p` and `q`, counter-clockwise about normal(dir).
  const auto strip = [&](glm::vec2 p, glm::vec2 q, auto normal) {
    const uint32_t first = static_cast<uint32_t>(b.mesh().positions.size());
    for (int j = 0; j <= segments; ++j) {
      b.vertex(at(j, p.x, p.y), normal(dir(j)));
      b.vertex(at(j, q.x, q.y), normal(dir(j)));
    }
    for (uint32_t j = 0; j < static_cast<uint32_t>(segments); ++j)
      b.quad(first + 2 * j, first + 2 * j + 1, first + 2 * j + 3, first + 2 * j + 2);
  };
  strip({ri, h}, {ro, h}, [](glm::vec3) { return glm::vec3(0, 0, 1); });     // front
  strip({ro, -h}, {ri, -h}, [](glm::vec3) { return glm::vec3(0, 0, -1); });  // back
  strip({ro, h}, {ro, -h}, [](glm::vec3 d) { return d; });                   // extrados
  strip({ri, -h}, {ri, h}, [](glm::vec3 d) { return -d; });                  // intrados
  const glm::vec3 down(0, -1, 0);
  const auto end = [&](int j, float r0, float r1) {  // a foot, facing down
    const uint32_t v0 = b.vertex(at(j, r0, h), down), v1 = b.vertex(at(j, r0, -h), down);
    const uint32_t v2 = b.vertex(at(j, r1, -h), down), v3 = b.vertex(at(j, r1, h), down);
    b.quad(v0, v1, v2, v3);
  };
  end(0, ri, ro);
  end(segments, ro, ri);
  return b.take("arch");
}

namespace {

Mesh named(Mesh mesh, const char* name) {
  mesh.name = name;
  return mesh;
}

}  // namespace

std::vector<Mesh> make_room(const Extent& inside, const std::optional<Extent>& window, float wall) {
  const glm::vec3 lo = inside.min, hi = inside.max, w(wall);
  std::vector<Mesh> pieces;
  auto slab = [&](const glm::vec3& min, const glm::vec3& max, const char* name) {
    pieces.push_back(named(make_box(min, max), name));
  };
  slab(lo - w, {hi.x + wall, lo.y, hi.z + wall}, "floor");
  slab({lo.x - wall, hi.y, lo.z - wall}, hi + w, "ceiling");
  slab({lo.x - wall, lo.y, lo.z}, {lo.x, hi.y, hi.z}, "left wall");
  slab({hi.x, lo.y, lo.z}, {hi.x + wall, hi.y, hi.z}, "right wall");
  slab({lo.x - wall, lo.y, hi.z}, {hi.x + wall, hi.y, hi.z + wall}, "front wall");
  const float back = lo.z - wall;
  if (!window) {
    slab({lo.x - wall, lo.y, back}, {hi.x + wall, hi.y, lo.z}, "back wall");
    return pieces;
  }
  const glm::vec2 wx(window->min.x, window->max.x), wy(window->min.y, window->max.y);
  slab({lo.x - wall, lo.y, back}, {hi.x + wall, wy[0], lo.z}, "wall below window");
  slab({lo.x - wall, wy[1], back}, {hi.x + wall, hi.y, lo.z}, "wall above window");
  slab({lo.x - wall, wy[0], back}, {wx[0], wy[1], lo.z}, "wall left of window");
  slab({wx[1], wy[0], back}, {hi.x + wall, wy[1], lo.z}, "wall right of window");
  return pieces;
}

std::vector<Mesh> make_table(const glm::vec3& centre_of_top, glm::vec2 size) {
  const glm::vec3 c = centre_of_top, half(0.5f * size.x, 0.0f, 0.5f * size.y), thick(0.0f, 0.05f, 0.0f);
  std::vector<Mesh> pieces{named(make_box(c - half - thick, c + half), "table top")};
  const float leg = 0.06f, inset = 0.08f;  // half-width of a leg, its inset from the top's edge
  for (const float sx : {-1.0f, 1.0f})
    for (const float sz : {-1.0f, 1.0f}) {
      const glm::vec3 foot(c.x + sx * (half.x - inset), 0.0f, c.z + sz * (half.z - inset));
      const glm::vec3 top = foot + glm::vec3(0.0f, c.y - thick.y, 0.0f);
      pieces.push_back(named(make_box(foot - glm::vec3(leg, 0.0f, leg), top + glm::vec3(leg, 0.0f, leg)), "table leg"));
    }
  return pieces;
}

std::vector<Mesh> make_column(glm::vec2 at, float height, int segments) {
  const glm::vec3 foot(at.x, 0.0f, at.y);
  const float plinth = 0.3f, half = 0.45f, radius = 0.35f;  // the blocks' height and half-width
  const glm::vec3 top = foot + glm::vec3(0.0f, height, 0.0f);
  return {named(make_box(foot - glm::vec3(half, 0.0f, half), foot + glm::vec3(half, plinth, half)), "plinth"),
          named(make_cylinder(foot + glm::vec3(0.0f, plinth, 0.0f), radius, height - 2.0f * plinth, segments), "column"),
          named(make_box(top - glm::vec3(half, plinth, half), top + glm::vec3(half, 0.0f, half)), "capital")};
}

}  // namespace airlight::scene_mesh
