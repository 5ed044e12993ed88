#include "optics/airlight.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <glm/geometric.hpp>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

#include "optics/closed_form.hpp"
#include "optics/light.hpp"
#include "optics/test_support.hpp"

namespace airlight::optics {
namespace {

using testing::beam_airlight;
using testing::relative_error;

// Brute force: midpoint sum of V·e over n even steps. Its error is O(1/n) of the
// total per visibility or cone discontinuity and O(1/n²) elsewhere.
glm::dvec3 midpoint_sum(const Scene& scene, const Light& light, const Ray& ray, double t0, double t1,
                        const Visibility& visible, int n) {
  glm::dvec3 sum(0.0);
  const double h = (t1 - t0) / n;
  for (int i = 0; i < n; ++i) {
    const double x = t0 + (i + 0.5) * h;
    if (visible(ray.origin + x * ray.dir)) sum += inscatter(scene, light, ray, x);
  }
  return sum * h;
}

double worst_relative_error(const glm::dvec3& a, const glm::dvec3& b) {
  double worst = 0.0;
  for (int c = 0; c < 3; ++c) worst = std::max(worst, relative_error(a[c], b[c]));
  return worst;
}

struct Case {
  const char* name;
  Scene scene;
  Light light;
  Ray ray;
  double t1;
  Visibility visible;
};

Case point_light_box_and_shadow() {
  Case c{"point light, HG medium, Rayleigh box, shadow plane", {}, {}, {}, 12.0, {}};
  c.scene.medium.sigma_s = {0.05f, 0.03f, 0.02f};
  c.scene.medium.sigma_a = glm::vec3(0.01f);
  c.scene.medium.phase.lobes = {PhaseLobe{PhaseType::henyey_greenstein, 0.4f, 1.0f}};
  Volume box;
  box.min = {-1, 0, -6};
  box.max = {1, 1.5f, -3};
  box.sigma_s = {0.3f, 0.1f, 0.2f};
  box.sigma_a = glm::vec3(0.05f);
  box.phase.lobes = {PhaseLobe{PhaseType::rayleigh, 0.0f, 1.0f}};
  c.scene.volumes.push_back(box);
  c.light = testing::point_light({0.3f, 2.0f, -4.0f}, 30.0f);
  c.ray = {{0, 1, 3}, {0, 0, -1}};
  c.visible = [](const glm::dvec3& p) { return p.z > -2.0; };
  return c;
}

Case smooth_spot_murky() {
  Case c{"spot with smooth edge, murky medium, shadow plane", {}, {}, {}, 12.0, {}};
  c.scene.medium.sigma_s = glm::vec3(0.08f);
  c.scene.medium.sigma_a = glm::vec3(0.02f);
  c.scene.medium.phase.lobes = {PhaseLobe{PhaseType::murky, 0.0f, 1.0f}};
  c.light.type = LightType::spot;
  c.light.position = {0, 4, -2};
  c.light.direction = {0, -1, 0};
  c.light.intensity = {100, 80, 60};
  c.light.cone_deg = 30.0f;
  c.light.edge_deg = 8.0f;
  c.ray = {{-6, 1, -2}, {1, 0, 0}};
  c.visible = [](const glm::dvec3& p) { return p.x < 1.3; };
  return c;
}

Case sun_through_volume() {
  Case c{"directional light through an absorbing box, shadow plane", {}, {}, {}, 10.0, {}};
  c.scene.medium.sigma_s = glm::vec3(0.03f);
  c.scene.medium.sigma_a = glm::vec3(0.01f);
  Volume box;
  box.min = {-2, 1, -8};
  box.max = {2, 3, -4};
  box.sigma_s = {0.2f, 0.4f, 0.1f};
  box.sigma_a = glm::vec3(0.1f);
  box.phase.lobes = {PhaseLobe{PhaseType::hazy, 0.0f, 1.0f}};
  c.scene.volumes.push_back(box);
  c.light.type = LightType::directional;
  c.light.direction = glm::normalize(glm::vec3(0.3f, -1.0f, 0.2f));
  c.light.irradiance = glm::vec3(2.0f);
  c.ray = {{0, 0.5, 0}, glm::normalize(glm::dvec3(0.1, 0.1, -1))};
  c.visible = [](const glm::dvec3& p) { return p.x + p.z > -5.5; };
  return c;
}

Case simplified_hard_spot() {
  Case c{"simplified model, hard spot cone", {}, {}, {}, 10.0, {}};
  c.scene.medium.sigma_s = glm::vec3(0.1f);
  c.scene.light_model = {LightModelType::simplified, 0.5f, 1.0f};
  c.light.type = LightType::spot;
  c.light.position = {0, 3, -5};
  c.light.direction = glm::normalize(glm::vec3(0.2f, -1.0f, 0.1f));
  c.light.intensity = glm::vec3(20.0f);
  c.light.cone_deg = 25.0f;
  c.ray = {{-2, 0.5, 0}, glm::normalize(glm::dvec3(0.4, 0.05, -1))};
  c.visible = [](const glm::dvec3& p) { return p.z > -5.0; };
  return c;
}

Case spot_behind_the_eye() {
  // The apex lies behind the eye; the ray leaves the cone through its side.
  Case c{"spot apex behind the eye", testing::homogeneous_scene(0.05f, 0.02f), {}, {}, 15.0,
         [](const glm::dvec3&) { return true; }};
  c.light.type = LightType::spot;
  c.light.position = {0, 0, 5};
  c.light.direction = {0, 0, -1};
  c.light.intensity = glm::vec3(50.0f);
  c.light.cone_deg = 20.0f;
  c.light.edge_deg = 5.0f;
  c.ray = {{0, 0, 0}, glm::normalize(glm::dvec3(0.5, 0, -1))};
  return c;
}

TEST(AirlightQuadrature, MatchesBruteForceMidpointSums) {
  // 2e5 midpoint steps: O(1/n) = 5e-6 of the total per discontinuity (box faces,
  // cone, shadow). The differences shrink with the midpoint sum's step, so they
  // are its error, and the bound 1e-4 covers them (measured: docs/decisions.md,
  // Numerics). Quadrature: 1e-8.
  QuadratureSettings settings;
  settings.rel_tol = 1e-8;
  for (const Case& c : {point_light_box_and_shadow(), smooth_spot_murky(), sun_through_volume(),
                        simplified_hard_spot(), spot_behind_the_eye()}) {
    const glm::dvec3 q = airlight_quadrature(c.scene, c.light, c.ray, 0.0, c.t1, c.visible, settings);
    const glm::dvec3 m = midpoint_sum(c.scene, c.light, c.ray, 0.0, c.t1, c.visible, 200000);
    const double err = worst_relative_error(q, m);
    std::printf("%-55s quadrature %.9g, midpoint rel. diff %.2e\n", c.name, q.x, err);
    EXPECT_GT(q.x, 0.0) << c.name;
    EXPECT_LT(err, 1e-4) << c.name;
  }
}

TEST(AirlightQuadrature, NullVisibilityMeansLit) {
  const Case c = point_light_box_and_shadow();
  const glm::dvec3 a = airlight_quadrature(c.scene, c.light, c.ray, 0.0, c.t1, nullptr);
  const glm::dvec3 b =
      airlight_quadrature(c.scene, c.light, c.ray, 0.0, c.t1, [](const glm::dvec3&) { return true; });
  EXPECT_EQ(a, b);
  EXPECT_EQ(airlight_quadrature(c.scene, c.light, c.ray, 3.0, 3.0, nullptr), glm::dvec3(0.0));
}

TEST(AirlightQuadrature, RayAlongTheAxisThroughASpotApex) {
  // The spot at z = -5 faces the eye along the ray: lit up to the apex, dark
  // behind it; through the apex r is clamped at min_light_distance. The closed
  // form over [0, 5] sees the same clamped integrand (1e-7: quadrature tolerance).
  const Scene scene = testing::homogeneous_scene(0.05f, 0.02f);
  Light spot;
  spot.type = LightType::spot;
  spot.position = {0, 0, -5};
  spot.direction = {0, 0, 1};
  spot.intensity = glm::vec3(10.0f);
  spot.cone_deg = 15.0f;
  const Ray ray{{0, 0, 0}, {0, 0, -1}};
  QuadratureSettings settings;
  settings.rel_tol = 1e-9;
  const double q = airlight_quadrature(scene, spot, ray, 0.0, 9.0, nullptr, settings).x;
  const double c = sun_airlight(0.05, 0.07f, 10.0, ray.origin, ray.dir, {0, 0, -5}, 5.0);
  EXPECT_TRUE(std::isfinite(q));
  EXPECT_LT(relative_error(q, c), 1e-7);
}

TEST(AirlightQuadrature, VisibilityBoundaryIsLocated) {
  // A distant light in a thin medium makes e(x) constant to ~1e-8 along the
  // ray, so the integral is proportional to the lit length: the shadow edge at
  // t = 4.321 must be found to the bisection resolution, 1e-6 of the segment.
  const Scene scene = testing::homogeneous_scene(1e-6f, 0.0f);
  const Light light = testing::point_light({0, 1e5f, 0}, 1e10f);
  const Ray ray{{0, 0, 0}, {1, 0, 0}};
  QuadratureSettings settings;
  settings.rel_tol = 1e-10;
  const double lit = airlight_quadrature(scene, light, ray, 0.0, 10.0,
                                         [](const glm::dvec3& p) { return p.x < 4.321; }, settings).x;
  const double all = airlight_quadrature(scene, light, ray, 0.0, 10.0, nullptr, settings).x;
  EXPECT_NEAR(lit / all * 10.0, 4.321, 2e-5);  // 2e-5 = twice the resolution
}

// A hard spot 1 m above the ray pointing down, cone 45°: lit on t ∈ [15, 17] of
// [0, 32], and a shadow leaves only t ∈ [15.94, 15.97] lit. Over the whole ray the
// 32 panels are 1 m wide and that sliver fell between two nodes of [15, 16]
// (15.932 and 15.975): the quadrature returned 0 (the reference's nilsson_multiple
// was 4.7% off at 64×48, docs/decisions.md "The reference checked by brute
// force"). Over the cone's part the panels are 6 cm wide and find it.
TEST(AirlightQuadrature, ALitSliverInsideASpotsConeIsFound) {
  const Scene scene = testing::homogeneous_scene(0.05f, 0.02f);
  Light spot = testing::point_light({0, 0, 0}, 100.0f);
  spot.type = LightType::spot;
  spot.direction = {0, -1, 0};
  spot.cone_deg = 45.0f;
  const Ray ray{{-16, -1, 0}, {1, 0, 0}};
  const Visibility sliver = [](const glm::dvec3& p) { return p.x > -0.06 && p.x < -0.03; };
  const double q = airlight_quadrature(scene, spot, ray, 0.0, 32.0, sliver).x;
  const glm::dvec3 light(spot.position);
  const double exact = sun_airlight(0.05, 0.07, 100.0, ray.origin, ray.dir, light, 15.97) -
                       sun_airlight(0.05, 0.07, 100.0, ray.origin, ray.dir, light, 15.94);
  EXPECT_LT(relative_error(q, exact), 1e-5);  // the edges are located to 1e-6 of the 2 m part
}

// An unbounded sun in isotropic fog: e = σs/(4π)·E·exp(−σt·x) (no medium on its
// leg), so ∫ over [a, b] is σs/(4π)·E·(exp(−σt·a) − exp(−σt·b))/σt.
double sun_between(double a, double b) {
  return 0.05 / (4.0 * std::numbers::pi) * 2.0 * (std::exp(-0.07 * a) - std::exp(-0.07 * b)) / 0.07;
}

Light sun() {
  Light light;
  light.type = LightType::directional;
  light.direction = {0, -1, 0};
  light.irradiance = glm::vec3(2.0f);
  return light;
}

// Lit only on [4.997, 5.003] of [0, 32]: the sliver straddles the joint of two
// 1 m panels, between each one's end and its nearest node (0.43% of the panel
// in from it). Probing the nodes only, no panel saw it and the quadrature
// returned 0; the panels' ends are probed too now.
TEST(AirlightQuadrature, ALitSliverAtAPanelJointIsFound) {
  const Scene scene = testing::homogeneous_scene(0.05f, 0.02f);
  const Ray ray{{0, 0, 0}, {1, 0, 0}};
  const Visibility sliver = [](const glm::dvec3& p) { return p.x > 4.997 && p.x < 5.003; };
  const double q = airlight_quadrature(scene, sun(), ray, 0.0, 32.0, sliver).x;
  EXPECT_LT(relative_error(q, sun_between(4.997, 5.003)), 1e-4);  // the edges are located to 1e-6 of 32 m
}

// The point at t1 itself dark, as on a surface that shadows its own point: the
// change within resolution of the end splits nothing off and costs nothing.
TEST(AirlightQuadrature, ADarkEndPointLosesNothing) {
  const Scene scene = testing::homogeneous_scene(0.05f, 0.02f);
  const Ray ray{{0, 0, 0}, {1, 0, 0}};
  const Visibility end_dark = [](const glm::dvec3& p) { return p.x < 32.0; };
  const double q = airlight_quadrature(scene, sun(), ray, 0.0, 32.0, end_dark).x;
  EXPECT_LT(relative_error(q, sun_between(0.0, 32.0)), 1e-6);  // the smooth integral's tolerance, 1e-4, is met far better
}

// ---- beams against their closed form (test_support.hpp beam_airlight) ---------

// A view ray, and the part [a, b] of it inside the beam with s(t) = s0 + c·t there.
struct BeamCase {
  std::string name;
  Light light;
  Ray ray;
  double s0, c, a, b;
};

// The box x ∈ [-1, 1], y ∈ [-1, 4], z ∈ [-0.5, 0.5] (right = -x, up = +z).
Light vertical_beam() { return testing::beam_light({0, -1, 0}, {0, 0, 1}, Beam{{0, 4, 0}, {2, 1}, 5}, 3.0f); }

// A tilted beam and its frame (right, up, axis).
struct Tilted {
  Light light = testing::beam_light(glm::normalize(glm::vec3(1, -2, 0.5f)), {0, 1, 0},
                                    Beam{{0.5f, 5, -1}, {2, 1.5f}, 6}, 3.0f);
  glm::dvec3 origin{light.beam->origin}, axis{glm::normalize(glm::dvec3(light.direction))}, right, up;
  Tilted() { gobo_frame(light, right, up); }
  // The point at `along` right, `high` up and s downstream of the aperture's centre.
  glm::dvec3 at(double along, double high, double s) const { return origin + along * right + high * up + s * axis; }
};

BeamCase ray_across(std::string name, const Light& light, const glm::dvec3& origin, const glm::dvec3& dir,
                    double a, double b) {
  const glm::dvec3 axis = glm::normalize(glm::dvec3(light.direction));
  return {std::move(name), light, {origin, dir}, glm::dot(origin - glm::dvec3(light.beam->origin), axis),
          glm::dot(dir, axis), a, b};
}

std::vector<BeamCase> beam_cases() {
  const Light v = vertical_beam();
  const Tilted t;
  const double n = std::sqrt(1.04);  // |(1, -0.2, 0)|: x = -6 + t/n crosses x = ∓1 at t = 5n, 7n
  // An oblique wide beam entered through its aperture and left through its end:
  // a = -s0/c, b = (length - s0)/c.
  const Light wide = testing::beam_light(glm::normalize(glm::vec3(0.3f, -1, 0.2f)), {0, 1, 0},
                                         Beam{{0, 6, 0}, {100, 100}, 8}, 3.0f);
  const glm::dvec3 wide_origin(-1, 8, 1), wide_dir = glm::normalize(glm::dvec3(0.2, -1, -0.3));
  BeamCase oblique = ray_across("oblique: in through the aperture, out through the end", wide, wide_origin,
                                wide_dir, 0, 0);
  oblique.a = -oblique.s0 / oblique.c;
  oblique.b = (8.0 - oblique.s0) / oblique.c;
  // The camera inside the tilted beam, leaving through its end: b = (length - s0)/c.
  const glm::dvec3 down = glm::normalize(t.axis + 0.1 * t.right);
  BeamCase inside = ray_across("camera inside a tilted beam, out through the end", t.light, t.at(0, 0, 1.5),
                               down, 0.0, 0.0);
  inside.b = (6.0 - inside.s0) / inside.c;
  return {
      ray_across("across a vertical beam, descending", v, {-6, 3, 0.1}, glm::normalize(glm::dvec3(1, -0.2, 0)),
                 5 * n, 7 * n),
      oblique,
      inside,
      // Grazing: in the plane of a face (closed box: lit), and parallel to
      // faces of a tilted beam only to rounding (tiny slab slopes, no NaN).
      ray_across("in the plane of the up face", v, {-6, 2, 0.5}, {1, 0, 0}, 5, 7),
      ray_across("parallel to a tilted beam's faces, along right", t.light, t.at(-3, 0.3, 2), t.right, 2, 4),
      ray_across("parallel to a tilted beam's faces, along -up", t.light, t.at(0.4, 2, 2), -t.up, 1.25, 2.75),
      // Along the axis from inside: up the beam, s + t constant (k = 0), and down it.
      ray_across("along the axis toward the aperture", v, {0, 1, 0}, {0, 1, 0}, 0, 3),
      ray_across("along the axis away from the aperture", v, {0, 1, 0}, {0, -1, 0}, 0, 2),
      ray_across("along a tilted beam's axis from upstream", t.light, t.at(0.2, -0.3, -4), t.axis, 4, 10),
  };
}

// Inside the beam the integrand is a smooth exponential, which G7K15 on 32
// panels integrates to rounding; the ends come from slabs in double: 1e-10
// relative. Integrated over the whole ray instead, panels straddle the box's
// faces (jumps) and the adaptive rule stops at its rel_tol, far above 1e-10,
// so this test fails without the restriction (measured: docs/decisions.md, Beams).
TEST(AirlightQuadrature, UnoccludedBeamMatchesItsClosedForm) {
  const Scene scene = testing::homogeneous_scene(0.05f, 0.02f);
  const double sigma_s = scene.medium.sigma_s.x, sigma_t = scene.medium.sigma_t().x;
  const glm::dvec3 tint(0.5, 0.25, 1.0);
  for (BeamCase c : beam_cases()) {
    for (bool gobo : {false, true}) {
      if (gobo) c.light.gobo = std::make_shared<Image>(1, 1, glm::vec3(tint));  // uniform: the box's colour
      const glm::dvec3 q = airlight_quadrature(scene, c.light, c.ray, 0.0, 30.0, nullptr);
      const double e = beam_airlight(sigma_s, sigma_t, 3.0, c.s0, c.c, c.a, c.b);
      const glm::dvec3 expected = gobo ? e * tint : glm::dvec3(e);
      const double err = worst_relative_error(q, expected);
      std::printf("%-55s %s %.12g, rel. error %.2e\n", c.name.c_str(), gobo ? "gobo" : "    ", q.x, err);
      EXPECT_GT(e, 0.0) << c.name;
      EXPECT_LT(err, 1e-10) << c.name << (gobo ? " with gobo" : "");
    }
  }
}

TEST(AirlightQuadrature, RaysMissingABeamOrUpstreamOfItSeeNothing) {
  const Scene scene = testing::homogeneous_scene(0.05f, 0.02f);
  const Light v = vertical_beam();
  for (const Ray& ray : {Ray{{-6, 5, 0}, {1, 0, 0}},       // above the aperture
                         Ray{{-6, 2, 0.6}, {1, 0, 0}},     // beside the up face
                         Ray{{0, 10, 0}, {0, 1, 0}},       // upstream, looking away
                         Ray{{-6, 2, 0}, {-1, 0, 0}}})     // looking away from the box
    EXPECT_EQ(airlight_quadrature(scene, v, ray, 0.0, 30.0, nullptr), glm::dvec3(0.0));
}

}  // namespace
}  // namespace airlight::optics
