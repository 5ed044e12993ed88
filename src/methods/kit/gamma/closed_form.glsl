// Γ(t0 → t1), the unoccluded airlight of one light along a view segment in the
// medium that fills space, or in one component of a piecewise-homogeneous one:
// the GLSL twin of optics::gamma (src/optics/gamma.cpp). Bounded volumes and
// gobos are ignored (closed forms need one homogeneous medium: a method that
// wants volumes cuts the ray into pieces and sums their components; Γ uses the
// cone and the beam's box, not the light map's colours).
// Defining SUN_F_TABLE (and BINDING_SUN_TABLE) makes the isotropic Sun path
// read F from the SunTable texture; otherwise it integrates in the shader.
#include "methods/kit/frame/scene.glsl"
#include "optics/gamma.glsl"

#ifdef SUN_F_TABLE
layout(binding = BINDING_SUN_TABLE) uniform sampler2D sun_table;
#endif

// One component of the medium along a piece: its scattering σs, the phase of the medium that
// fills space (phase = -1) or of volume v (phase = v >= 0), and the extinction σt of everything
// that fills the piece (both legs). Inside a piece Γ is linear in σs·p, so a piece's airlight
// is the sum of its components' (Biri §5.2).
struct MediumComponent { vec3 sigma_s; vec3 sigma_t; int phase; };

// The frame's: the medium that fills space, alone.
MediumComponent filling_medium() { return MediumComponent(frame.medium_sigma_s, frame.medium_sigma_t, -1); }

// The component's phase function at cos θ. A constant m.phase folds the choice
// away (scene_defines.cpp), so the medium pays for no volume's lobes.
float component_phase(MediumComponent m, float c) { return m.phase < 0 ? medium_phase(c) : VOLUME_PHASE(m.phase, c); }

// Whether its phase is isotropic: Sun et al.'s path applies.
bool isotropic_component(MediumComponent m) { return m.phase < 0 ? MEDIUM_ISOTROPIC != 0 : VOLUME_ISOTROPIC(m.phase); }

// Sun et al. (Kingston eqs. 36-40) over [a, b] per channel, times the eye's
// extinction to a (in the closed form's exp). Γ is linear in the intensity: in
// grey media one channel with I = 1, times the light's colour, gives all three
// (GREY_MEDIA covers the volumes too, so a component's σs and σt, sums of grey σ, are grey).
float sun_channel(int c, MediumComponent m, vec3 eye, vec3 dir, vec3 light, float I, float a, float b) {
  vec3 origin = eye + a * dir;
  float depth = m.sigma_t[c] * a;
#ifdef SUN_F_TABLE
  return sun_airlight_table(sun_table, m.sigma_s[c], m.sigma_t[c], I, origin, dir, light, b - a, depth);
#else
  return sun_airlight_ray(m.sigma_s[c], m.sigma_t[c], I, origin, dir, light, b - a, depth);
#endif
}

vec3 sun_piece(int i, MediumComponent m, vec3 eye, vec3 dir, float a, float b) {
#if GREY_MEDIA
  return sun_channel(0, m, eye, dir, LIGHT(i).position, 1.0, a, b) * LIGHT(i).color;
#else
  vec3 sum;
  for (int c = 0; c < 3; ++c) sum[c] = sun_channel(c, m, eye, dir, LIGHT(i).position, LIGHT(i).color[c], a, b);
  return sum;
#endif
}

// Nilsson 2.5: no extinction and its own isotropic phase, so only σs is the component's.
vec3 nilsson_piece(int i, MediumComponent m, vec3 eye, vec3 dir, float a, float b) {
#if GREY_MEDIA
  return nilsson_airlight(m.sigma_s.r, 1.0, frame.light_model_a0, frame.light_model_a1, eye, dir,
                          LIGHT(i).position, a, b) * LIGHT(i).color;
#else
  vec3 sum;
  for (int c = 0; c < 3; ++c)
    sum[c] = nilsson_airlight(m.sigma_s[c], LIGHT(i).color[c], frame.light_model_a0, frame.light_model_a1, eye,
                              dir, LIGHT(i).position, a, b);
  return sum;
#endif
}

// gamma.cpp biri_angular: ∫ p(cos θ)·cone·exp(-σt(x + r))/r² dx over [t0, t1],
// Biri's angle φ through s = asinh((x - xs)/h): dx/r² = ds/(h cosh s), cos θ = -tanh s.
vec3 biri_angular(int i, MediumComponent m, vec3 eye, vec3 dir, float t0, float t1) {
  vec3 light = LIGHT(i).position, delta = light - eye;
  float xs = dot(delta, dir);
  vec3 off = delta - xs * dir;
  float h_true = length(off), h = max(h_true, MIN_LIGHT_DISTANCE);
  vec3 normal = h_true > 0.0 ? off / h_true : normalize(cross(dir, vec3(dir.y, dir.z, -dir.x)));
  bool smooth_edge = light_types[i] == LIGHT_SPOT && light_edges[i];
  vec3 sigma_t = simplified_model() ? vec3(0.0) : m.sigma_t;  // T = 1 (Nilsson 2.5)
  float fast = max(sigma_t.r, max(sigma_t.g, sigma_t.b)), slow = min(sigma_t.r, min(sigma_t.g, sigma_t.b));
  float s0 = stable_asinh((t0 - xs) / h), s1 = stable_asinh((t1 - xs) / h);
  float e0 = h * exp(s0);
  vec3 sum = vec3(0.0);
  float a = s0;
  for (int panel = 0; panel < BIRI_MAX_PANELS && a < s1; ++panel) {
    float grow = fast > 0.0 ? log1p_nonneg(BIRI_PANEL_GROWTH / (fast * h * exp(a))) : BIRI_MAX_PANEL;
    float b = min(s1, a + min(BIRI_MAX_PANEL, grow));
    for (int k = 0; k < 8; ++k) {
      float s = 0.5 * (a + b) + 0.5 * (b - a) * (k < 4 ? -GAUSS8_X[k] : GAUSS8_X[k - 4]);
      float w = 0.5 * (b - a) * GAUSS8_W[k % 4];
      float f = simplified_model() ? INV_4PI : component_phase(m, -tanh(s));
      if (simplified_model()) {  // its falloff over the physical one's, r²/(a1·r² + a0) (Nilsson eq. 2.13)
        float r2 = h * h * cosh(s) * cosh(s);
        f *= r2 / (frame.light_model_a1 * r2 + frame.light_model_a0);
      }
      if (smooth_edge)
        f *= spot_cone(LIGHT(i).direction, LIGHT(i).cone, LIGHT(i).edge,
                       normalize(tanh(s) * dir - normal / cosh(s)));
      sum += w * f / cosh(s) * exp(-sigma_t * (e0 * expm1_nonneg(s - s0)));
    }
    if (slow * e0 * expm1_nonneg(b - s0) > BIRI_TAIL_GROWTH) break;
    a = b;
  }
  return sum * exp(-sigma_t * (t0 + length(light - (eye + t0 * dir)))) / h;
}

// One lit piece of a point or spot light (gamma.cpp local_piece); 0 if empty.
// The closed forms the scene's model and media rule out are left out by the
// preprocessor, not by constants: Mesa inlines every call before the
// conditions fold, and the dead Sun and Nilsson forms inlined at every
// local_piece were half of a program's link (docs/decisions.md, "The first
// frame (issue 28)").
vec3 local_piece(int i, MediumComponent m, vec3 eye, vec3 dir, float a, float b) {
  if (!(b > a)) return vec3(0.0);
  bool smooth_edge = light_types[i] == LIGHT_SPOT && light_edges[i];
#if SIMPLIFIED_MODEL
  if (!smooth_edge) return nilsson_piece(i, m, eye, dir, a, b);  // the edge has no closed form
#elif ISOTROPIC_COMPONENTS
  if (isotropic_component(m) && !smooth_edge) return sun_piece(i, m, eye, dir, a, b);
#endif
  return m.sigma_s * LIGHT(i).color * biri_angular(i, m, eye, dir, a, b);
}

// A hard-edged spot: one local_piece per cone interval. Its own loop, not
// spot_gamma's: on llvmpipe a lane runs every iteration any lane of its group
// runs, so the 5 pieces per interval a smooth edge needs made a hard edge run
// 4 empty closed forms beside its 1 (docs/decisions.md, "Γ's cost").
vec3 hard_spot_gamma(int i, MediumComponent m, vec3 eye, vec3 dir, ConeIntervals lit) {
  if (light_narrow[i]) {  // a constant: below 90° the cone is one piece, and no loop is needed
    vec2 piece = lit.count > 0 ? lit.piece[0] : vec2(0.0);
    return local_piece(i, m, eye, dir, piece.x, piece.y);
  }
  vec3 sum = vec3(0.0);
  for (int k = 0; k < lit.count; ++k) {
    vec2 piece = k == 0 ? lit.piece[0] : lit.piece[1];  // by a select: indexed by k, Mesa would unroll the loop
    sum += local_piece(i, m, eye, dir, piece.x, piece.y);
  }
  return sum;
}

// sin and cos of spot i's cone from its tan_cone by one root, where the frame
// gives it (cones below 90°: light_narrow, a constant), instead of a sin and a
// cos per pixel.
vec2 spot_sin_cos(int i) {
  if (!light_narrow[i]) return vec2(sin(LIGHT(i).cone), cos(LIGHT(i).cone));
  float t = LIGHT(i).tan_cone;
  float c = 1.0 / sqrt(1.0 + t * t);
  return vec2(t * c, c);
}

// A spot: its cone_intervals (hard cut at the cone), each cut again at the
// inner cone's ends under a smooth edge (gamma.cpp spot_gamma): those pieces
// lie inside the outer one, in ascending order. Their ends are gathered first
// (per outer piece: its start, the core's ends, collapsed onto its end where
// absent, its end), and the up to 2 × 5 pieces summed by one local_piece in a
// loop the compiler cannot unroll: unrolled, ten copies of it (Sun's closed form
// per channel, Biri's quadrature) made shaders with a few spots and volumes
// take minutes to compile on llvmpipe.
vec3 spot_gamma(int i, MediumComponent m, vec3 eye, vec3 dir, float t0, float t1) {
  vec3 apex = LIGHT(i).position, axis = LIGHT(i).direction;
  float cone = LIGHT(i).cone, inner = cone - LIGHT(i).edge;
  ConeIntervals lit = cone_intervals(apex, axis, spot_sin_cos(i), eye, dir, t0, t1);
#if HAS_HARD_SPOT
  if (!light_edges[i]) return hard_spot_gamma(i, m, eye, dir, lit);  // a constant: folds away
#endif
#if HAS_SMOOTH_SPOT  // left out before it is inlined where every spot is hard (scene.glsl)
  bool cut = inner > 0.0;
  float ends[12];
  for (int k = 0; k < 2; ++k) {
    float start = lit.piece[k].x, end = lit.piece[k].y;
    ConeIntervals core = ConeIntervals(0, vec2[2](vec2(0.0), vec2(0.0)));
    if (cut && k < lit.count) core = cone_intervals(apex, axis, inner, eye, dir, start, end);
    ends[6 * k] = start;
    for (int j = 0; j < 2; ++j) {
      ends[6 * k + 1 + 2 * j] = j < core.count ? core.piece[j].x : end;
      ends[6 * k + 2 + 2 * j] = j < core.count ? core.piece[j].y : end;
    }
    ends[6 * k + 5] = end;
  }
  vec3 sum = vec3(0.0);
  for (int n = 0; n < 5 * lit.count; ++n) {
    float a = 0.0, b = 0.0;
    for (int q = 0; q < 10; ++q)  // ends[] by selects: indexed by n, Mesa would unroll the loop
      if (q == n) {
        a = ends[q + q / 5];
        b = ends[q + q / 5 + 1];
      }
    sum += local_piece(i, m, eye, dir, a, b);
  }
  return sum;
#else
  return vec3(0.0);  // unreached: every spot returned above
#endif
}

// gamma.cpp directional: the exact exponential form, over the beam's box if any.
vec3 directional_gamma(int i, MediumComponent m, vec3 eye, vec3 dir, float t0, float t1) {
  vec3 travel = LIGHT(i).direction;
  bool simplified = simplified_model();
  float p = simplified ? INV_4PI : component_phase(m, dot(-travel, dir));
  float along = 0.0, s_start = 0.0;
  if (has_beam(i)) {
    Beam beam = light_beam(i);
    vec2 inside = beam_interval(beam, eye, dir, t0, t1);
    if (!(inside.x < inside.y)) return vec3(0.0);
    t0 = inside.x;
    t1 = inside.y;
    along = dot(dir, travel);
    s_start = max(beam_depth(beam, eye + t0 * dir), 0.0);
  }
  vec3 sigma_t = simplified ? vec3(0.0) : m.sigma_t;
  return m.sigma_s * p * LIGHT(i).color * exp(-sigma_t * (t0 + s_start)) *
         exponential_length(sigma_t * (1.0 + along), t1 - t0);
}

// Γ of light i scattered by component m along eye + t·dir (unit dir) over
// [t0, t1], a piece that m's σt fills (optics::gamma with that Medium).
// The kinds of light the scene has no light of are left out by the
// preprocessor (local_piece).
vec3 component_airlight(int i, MediumComponent m, vec3 eye, vec3 dir, float t0, float t1) {
#if HAS_DIRECTIONAL_LIGHT
  if (light_types[i] == LIGHT_DIRECTIONAL) return directional_gamma(i, m, eye, dir, t0, t1);
#endif
#if HAS_POINT_LIGHT
  if (light_types[i] == LIGHT_POINT) return local_piece(i, m, eye, dir, t0, t1);
#endif
#if HAS_SPOT_LIGHT
  return spot_gamma(i, m, eye, dir, t0, t1);
#else
  return vec3(0.0);  // no light is left
#endif
}

// Γ of light i in the medium that fills space: the entry point of the `analytic` method.
vec3 closed_form_airlight(int i, vec3 eye, vec3 dir, float t0, float t1) {
  return component_airlight(i, filling_medium(), eye, dir, t0, t1);
}
