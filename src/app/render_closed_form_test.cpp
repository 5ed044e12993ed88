// Done-when of the foundation: `airlight render --builtin teapot_spot --method
// reference --pass airlight` writes finite values that match the Sun et al.
// closed form wherever no occluder is involved.
#include "core/image_io.hpp"
#include "core/test_paths.hpp"
#include "geometry/camera.hpp"
#include "optics/closed_form.hpp"
#include "optics/light.hpp"

#include <airlight/scene.hpp>
#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <unistd.h>

namespace airlight {
namespace {

constexpr int width = 128, height = 96;

struct Sphere {
  glm::dvec3 centre{0.0};
  double radius = 0.0;
};

// A sphere around every mesh but the floor: the occluders.
Sphere occluder_bound(const Scene& scene) {
  glm::dvec3 lo(1e30), hi(-1e30);
  for (const auto& mesh : scene.meshes)
    if (mesh.name != "floor")
      for (const auto& p : mesh.positions) lo = glm::min(lo, glm::dvec3(p)), hi = glm::max(hi, glm::dvec3(p));
  return {(lo + hi) * 0.5, glm::length(hi - lo) * 0.5};
}

// Where the ray enters the floor slab (an axis-aligned box), or the far plane.
double view_distance(const Scene& scene, const optics::Ray& ray) {
  const Mesh* floor = nullptr;
  for (const auto& mesh : scene.meshes)
    if (mesh.name == "floor") floor = &mesh;
  glm::dvec3 lo(1e30), hi(-1e30);
  for (const auto& p : floor->positions) lo = glm::min(lo, glm::dvec3(p)), hi = glm::max(hi, glm::dvec3(p));
  double t_in = 0.0, t_out = 1e30;
  for (int a = 0; a < 3; ++a) {
    const double t0 = (lo[a] - ray.origin[a]) / ray.dir[a], t1 = (hi[a] - ray.origin[a]) / ray.dir[a];
    t_in = std::max(t_in, std::min(t0, t1));
    t_out = std::min(t_out, std::max(t0, t1));
  }
  const double far = geometry::far_distance(scene.camera, ray.dir);
  return t_in < t_out ? std::min(t_in, far) : far;
}

// The lit interval [a, b] of the ray inside the hard-edged cone, found by dense
// sampling and bisection: independent of the optics' own cone clipping.
bool cone_interval(const Light& light, const optics::Ray& ray, double d, double* a, double* b) {
  auto inside = [&](double x) { return optics::spot_cone(light, glm::normalize(ray.origin + x * ray.dir - glm::dvec3(light.position))) > 0.5; };
  auto boundary = [&](double lo, double hi) {
    for (int i = 0; i < 60; ++i) {
      const double mid = 0.5 * (lo + hi);
      (inside(mid) == inside(lo) ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
  };
  const int n = 2000;
  int first = -1, last = -1;
  for (int i = 0; i <= n; ++i)
    if (inside(d * i / n)) (first < 0 ? first : last) = i, last = i;
  if (first < 0) return false;
  *a = first == 0 ? 0.0 : boundary(d * (first - 1) / n, d * first / n);
  *b = last == n ? d : boundary(d * last / n, d * (last + 1) / n);
  return true;
}

// Is every point of [a, b] seen from the light well clear of the occluders' bound?
bool clear_of_occluders(const Light& light, const Sphere& s, const optics::Ray& ray, double a, double b) {
  const glm::dvec3 L(light.position);
  const double half_angle = std::asin(std::min(1.0, s.radius / glm::length(s.centre - L)));
  const glm::dvec3 to_centre = glm::normalize(s.centre - L);
  for (int i = 0; i <= 400; ++i) {
    const glm::dvec3 x = ray.origin + (a + (b - a) * i / 400.0) * ray.dir;
    const double angle = std::acos(std::clamp(glm::dot(glm::normalize(x - L), to_centre), -1.0, 1.0));
    if (angle < half_angle + 0.02) return false;  // 0.02 rad margin for the sampling step
  }
  return true;
}

TEST(RenderClosedForm, TeapotSpotMatchesSunWhereNoOccluderIsInvolved) {
  const std::filesystem::path out =
      std::filesystem::temp_directory_path() / ("airlight_closed_form_" + std::to_string(::getpid()) + ".pfm");
  const std::string command = test::airlight_exe().string() +
                              " render --builtin teapot_spot --method reference --pass airlight --size 128x96 --out " +
                              out.string();
  ASSERT_EQ(std::system(command.c_str()), 0);
  const Image image = read_image(out);
  const Scene scene = builtin_scene("teapot_spot");
  ASSERT_EQ(scene.lights.size(), 1u);
  const Light& light = scene.lights[0];
  // The closed form is for an isotropic phase and a hard cone (Nilsson eq. 2.9).
  ASSERT_EQ(scene.medium.phase.lobes[0].type, PhaseType::isotropic);
  ASSERT_EQ(light.edge_deg, 0.0f);
  const Sphere occluders = occluder_bound(scene);
  int compared = 0;
  double worst = 0.0;
  for (int j = 0; j < height; ++j)
    for (int i = 0; i < width; ++i) {
      const glm::vec3 value = image.at(i, j);
      for (int c = 0; c < 3; ++c) ASSERT_TRUE(std::isfinite(value[c]) && value[c] >= 0.0f) << i << "," << j;
      const optics::Ray ray = geometry::primary_ray(scene.camera, width, height, i + 0.5, j + 0.5);
      const double d = view_distance(scene, ray);
      double a = 0.0, b = 0.0;
      if (!cone_interval(light, ray, d, &a, &b) || !clear_of_occluders(light, occluders, ray, a, b)) continue;
      for (int c = 0; c < 3; ++c) {
        const double s = scene.medium.sigma_s[c], t = scene.medium.sigma_t()[c], I = light.intensity[c];
        auto gamma = [&](double x) {
          return optics::sun_airlight(s, t, I, ray.origin, ray.dir, glm::dvec3(light.position), x);
        };
        const double expected = gamma(b) - gamma(a);
        worst = std::max(worst, std::abs(value[c] - expected) / expected);
      }
      ++compared;
    }
  std::printf("compared %d unoccluded pixels; worst relative error %.2e\n", compared, worst);
  EXPECT_GT(compared, width * height / 10);  // the shaft covers a good part of the image
  // 0.1% is the reference's accuracy target (rel_tol 1e-3); float storage adds 2^-24.
  EXPECT_LT(worst, 1e-3);
  std::filesystem::remove(out);
}

}  // namespace
}  // namespace airlight
