#pragma once
// Globally adaptive Gauss–Kronrod (G7K15) integration, in double precision, for
// scalar or RGB integrands: the engine behind airlight_quadrature and the closed
// forms' angular integrals (QUADPACK's QAG strategy: always bisect the panel with
// the largest error until the summed error meets the target).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <glm/common.hpp>
#include <glm/vec3.hpp>
#include <optional>
#include <queue>
#include <vector>

namespace airlight::optics::gk {

inline constexpr int node_count = 15;

// G7K15 abscissae on [-1, 1] in ascending order, Kronrod weights, and the
// Gauss weights of the odd-indexed nodes (QUADPACK qk15).
inline constexpr std::array<double, 8> kronrod_x = {
    0.991455371120812639206854697526329, 0.949107912342758524526189684047851,
    0.864864423359769072789712788640926, 0.741531185599394439863864773280788,
    0.586087235467691130294144845693013, 0.405845151377397166906606412076961,
    0.207784955007898467600689403773245, 0.0};
inline constexpr std::array<double, 8> kronrod_w = {
    0.022935322010529224963732008058970, 0.063092092629978553290700663189204,
    0.104790010322250183839876322541518, 0.140653259715525918745189590510238,
    0.169004726639267902826583426598550, 0.190350578064785409913256402421014,
    0.204432940075298892414161999234649, 0.209482141084727828012999174891714};
inline constexpr std::array<double, 4> gauss_w = {
    0.129484966168869693270611432679082, 0.279705391489276667901467771423780,
    0.381830050505118944950369775488975, 0.417959183673469387755102040816327};

// The 15 nodes of the rule on [a, b], ascending.
inline std::array<double, node_count> nodes(double a, double b) {
  const double centre = 0.5 * (a + b), half = 0.5 * (b - a);
  std::array<double, node_count> x{};
  for (int i = 0; i < 8; ++i) {
    x[i] = centre - half * kronrod_x[i];
    x[node_count - 1 - i] = centre + half * kronrod_x[i];
  }
  return x;
}

// Per-component helpers so one engine serves double and glm::dvec3.
inline double magnitude(double v) { return std::abs(v); }
inline glm::dvec3 magnitude(const glm::dvec3& v) { return glm::abs(v); }
inline double worst(double v) { return v; }
inline double worst(const glm::dvec3& v) { return std::max({v.x, v.y, v.z}); }

template <class Value>
struct Estimate {
  Value integral{0.0};
  Value error{0.0};  // |K15 - G7|: conservative for smooth integrands
};

// The rule applied to values fx at nodes(a, b).
template <class Value>
Estimate<Value> apply(double a, double b, const std::array<Value, node_count>& fx) {
  const double half = 0.5 * (b - a);
  Value kronrod = fx[7] * kronrod_w[7];
  Value gauss = fx[7] * gauss_w[3];
  for (int i = 0; i < 7; ++i) {
    const Value pair = fx[i] + fx[node_count - 1 - i];
    kronrod += pair * kronrod_w[i];
    if (i % 2 == 1) gauss += pair * gauss_w[i / 2];
  }
  return {kronrod * half, magnitude((kronrod - gauss) * half)};
}

template <class Value, class F>
Estimate<Value> rule(F&& f, double a, double b) {
  const std::array<double, node_count> x = nodes(a, b);
  std::array<Value, node_count> fx;
  for (int i = 0; i < node_count; ++i) fx[i] = f(x[i]);
  return apply<Value>(a, b, fx);
}

struct Settings {
  double rel_tol = 1e-10;  // of the whole integral's magnitude, per component
  double abs_tol = 0.0;    // absolute floor of the error target
  int max_depth = 40;      // bisections of an initial panel
  int max_panels = 20000;  // stop refining beyond this many panels
};

// A panel's evaluation: an estimate, or a request to split it at [lo, hi] (a
// located discontinuity; the sliver between them becomes a panel of its own).
template <class Value>
struct Evaluation {
  Estimate<Value> estimate;
  std::optional<std::array<double, 2>> split;
};

// ∫ over [breaks.front(), breaks.back()], the integrand smooth between breaks.
// evaluate(a, b) -> Evaluation<Value>.
template <class Value, class Evaluate>
Value integrate_panels(Evaluate&& evaluate, const std::vector<double>& breaks,
                       const Settings& settings) {
  struct Panel {
    double a, b;
    int depth;
    Estimate<Value> e;
    double key;
  };
  std::vector<Panel> done, pending;
  // Evaluates [a, b] at `depth`, following split requests (bounded by max_panels).
  auto add = [&](double a0, double b0, int depth) {
    std::vector<std::array<double, 2>> stack{{a0, b0}};
    while (!stack.empty()) {
      const auto [a, b] = stack.back();
      stack.pop_back();
      Evaluation<Value> ev = evaluate(a, b);
      const bool may_split = int(done.size() + pending.size() + stack.size()) < settings.max_panels;
      if (ev.split && may_split && (*ev.split)[0] > a && (*ev.split)[1] < b) {
        const auto [lo, hi] = *ev.split;
        stack.push_back({a, lo});
        stack.push_back({lo, hi});
        stack.push_back({hi, b});
        continue;
      }
      pending.push_back({a, b, depth, ev.estimate, 0.0});
    }
  };
  for (std::size_t i = 0; i + 1 < breaks.size(); ++i)
    if (breaks[i + 1] > breaks[i]) add(breaks[i], breaks[i + 1], 0);

  // The coarse pass fixes the scale that ranks panels.
  Value total{0.0}, error{0.0};
  for (const Panel& p : pending) total += p.e.integral, error += p.e.error;
  const Value scale = magnitude(total) + Value(1e-300);
  auto key_of = [&](const Panel& p) { return worst(p.e.error / scale); };
  auto less = [](const Panel& x, const Panel& y) { return x.key < y.key; };
  std::priority_queue<Panel, std::vector<Panel>, decltype(less)> heap(less);
  for (Panel& p : pending) p.key = key_of(p), heap.push(p);
  pending.clear();

  auto converged = [&] {
    const Value target = magnitude(total) * settings.rel_tol + Value(settings.abs_tol);
    return worst(error - target) <= 0.0;
  };
  while (!heap.empty() && !converged() &&
         int(heap.size() + done.size()) < settings.max_panels) {
    Panel p = heap.top();
    heap.pop();
    if (p.depth >= settings.max_depth || !(p.b - p.a > 0.0) || p.key == 0.0) {
      done.push_back(p);
      if (p.key == 0.0) break;  // every remaining panel is exact
      continue;
    }
    total -= p.e.integral, error -= p.e.error;
    const double mid = 0.5 * (p.a + p.b);
    add(p.a, mid, p.depth + 1);
    add(mid, p.b, p.depth + 1);
    for (Panel& q : pending) {
      total += q.e.integral, error += q.e.error;
      q.key = key_of(q);
      heap.push(q);
    }
    pending.clear();
  }
  // Re-sum from the panels: the running sums drift by rounding.
  Value sum{0.0};
  for (const Panel& p : done) sum += p.e.integral;
  for (; !heap.empty(); heap.pop()) sum += heap.top().e.integral;
  return sum;
}

// Plain adaptive integration of a smooth f over [a, b] (with optional interior breaks).
template <class Value, class F>
Value integrate(F&& f, std::vector<double> breaks, const Settings& settings = {}) {
  auto evaluate = [&](double a, double b) { return Evaluation<Value>{rule<Value>(f, a, b), {}}; };
  return integrate_panels<Value>(evaluate, breaks, settings);
}

}  // namespace airlight::optics::gk
