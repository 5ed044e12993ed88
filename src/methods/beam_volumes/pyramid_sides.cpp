#include "methods/beam_volumes/pyramid_sides.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>
#include <unordered_map>
#include <glm/geometric.hpp>

namespace airlight::methods {
namespace {

// How the light sees a point: on the sphere of radius `reach` about a point light, or across a
// directional light's direction.
class LightView {
public:
  LightView(const glm::dvec4& apex, double reach)
      : directional_(apex.w == 0.0), light_(directional_ ? glm::normalize(glm::dvec3(apex)) : glm::dvec3(apex)),
        reach_(reach) {}
  bool directional() const { return directional_; }
  const glm::dvec3& light() const { return light_; }  // a point light's position; toward a directional one
  glm::dvec3 seen(const glm::dvec3& x) const {
    return directional_ ? x - glm::dot(x, light_) * light_ : light_ + reach_ * glm::normalize(x - light_);
  }
  // The unit normal of the plane through the light and seen points p and q.
  glm::dvec3 normal(const glm::dvec3& p, const glm::dvec3& q) const {
    return glm::normalize(directional_ ? glm::cross(q - p, light_) : glm::cross(p - light_, q - light_));
  }
  // Distance along the line of sight: from a point light, or downstream of a directional one.
  double depth(const glm::dvec3& x) const { return directional_ ? -glm::dot(x, light_) : glm::distance(x, light_); }

private:
  bool directional_;
  glm::dvec3 light_;
  double reach_;
};

// A side with the lines of sight through its ends: ids of the welded seen points.
struct Side {
  int a, b, from, to;
};

// One plane of sides through the light: where a line of sight lies in it (the angle about a
// point light, the distance across a directional one), and where it meets a side's edge.
class SidePlane {
public:
  SidePlane(const LightView& view, const glm::dvec3& p, const glm::dvec3& q)
      : view_(view), n_(view.normal(p, q)),
        u_(glm::normalize(view.directional() ? q - p : p - view.light())), v_(glm::cross(n_, u_)) {}

  double coordinate(const glm::dvec3& seen) const {
    if (view_.directional()) return glm::dot(seen, u_);
    const glm::dvec3 r = seen - view_.light();
    return std::atan2(glm::dot(r, v_), glm::dot(r, u_));
  }

  // The point of edge a → b on the line of sight through `seen`.
  glm::dvec3 meet(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& seen) const {
    double s = 0.0;
    if (view_.directional()) {
      s = glm::dot(seen - a, u_) / glm::dot(b - a, u_);
    } else {
      const glm::dvec3 sight = seen - view_.light();
      s = glm::dot(glm::cross(view_.light() - a, sight), n_) / glm::dot(glm::cross(b - a, sight), n_);
    }
    return a + std::clamp(s, 0.0, 1.0) * (b - a);
  }

private:
  const LightView& view_;
  glm::dvec3 n_, u_, v_;
};

void emit(std::vector<WeightedTriangle>& out, const glm::dvec4& a, glm::dvec4 b, glm::dvec4 c, int weight) {
  if (weight == 0 || a == b || b == c || c == a) return;
  if (weight < 0) std::swap(b, c);
  out.push_back({{a, b, c}, std::abs(weight)});
}

class SideSum {
public:
  SideSum(const geometry::ConformingSet& set, const geometry::ConformingSet& sight, const LightView& view,
          const glm::dvec4& apex, double tolerance, std::vector<WeightedTriangle>& out)
      : set_(set), sight_(sight), view_(view), apex_(apex), tolerance_(tolerance), out_(out) {}

  // The sides grouped by plane: two that share a line of sight and lie in one plane (within
  // the tolerance) are in the same group, and so on along the chain.
  std::vector<std::vector<Side>> planes(const std::vector<Side>& sides) const {
    std::vector<size_t> parent(sides.size());
    std::iota(parent.begin(), parent.end(), size_t{0});
    const auto root = [&](size_t i) {
      while (parent[i] != i) i = parent[i] = parent[parent[i]];
      return i;
    };
    std::unordered_map<int, std::vector<size_t>> on_line;
    for (size_t i = 0; i < sides.size(); ++i) {
      on_line[sides[i].from].push_back(i);
      on_line[sides[i].to].push_back(i);
    }
    for (const auto& [line, list] : on_line)
      for (size_t i = 0; i < list.size(); ++i)
        for (size_t j = i + 1; j < list.size(); ++j)
          if (coplanar(sides[list[i]], sides[list[j]])) parent[root(list[j])] = root(list[i]);
    std::vector<std::vector<Side>> groups;
    std::unordered_map<size_t, size_t> group_of_root;
    for (size_t i = 0; i < sides.size(); ++i) {
      const auto [it, added] = group_of_root.try_emplace(root(i), groups.size());
      if (added) groups.emplace_back();
      groups[it->second].push_back(sides[i]);
    }
    return groups;
  }

  // One plane's sides cut at every line of sight through an end of one of them; across each
  // cut, the sides sorted far to near and summed outward from the farthest: the band between
  // two consecutive ones carries the sum of the windings beyond it, and what is left from the
  // nearest to the light (nothing where the pieces tile the light's view) stays a triangle to
  // the apex. Any order gives the same sum; far to near gives bands that do not overlap.
  void sum(const std::vector<Side>& sides) {
    const SidePlane plane(view_, sight_.vertex(sides[0].from), sight_.vertex(sides[0].to));
    std::vector<std::pair<double, int>> lines;  // (coordinate, line), in order across the plane
    for (const Side& s : sides)
      for (int line : {s.from, s.to}) lines.emplace_back(plane.coordinate(sight_.vertex(line)), line);
    std::sort(lines.begin(), lines.end());
    lines.erase(std::unique(lines.begin(), lines.end()), lines.end());
    if (!view_.directional()) from_widest_gap(lines);
    std::unordered_map<int, size_t> index;
    for (size_t k = 0; k < lines.size(); ++k) index[lines[k].second] = k;
    std::vector<std::vector<std::pair<Side, int>>> across(lines.size());  // per cut: sides and windings
    for (const Side& s : sides) {
      const size_t from = index[s.from], to = index[s.to];
      // A side across the widest gap (sides all around the light in one plane) stays whole.
      if (!view_.directional() && std::abs(lines[from].first - lines[to].first) > std::numbers::pi) {
        whole(s);
        continue;
      }
      // The side (b, a, apex) runs from b to a: with the coordinate, +1.
      for (size_t k = std::min(from, to); k < std::max(from, to); ++k) across[k].emplace_back(s, to < from ? 1 : -1);
    }
    for (size_t k = 0; k + 1 < lines.size(); ++k) sum_across(plane, across[k], lines[k].second, lines[k + 1].second);
  }

  void whole(const Side& s) { emit(out_, point(s.b), point(s.a), apex_, 1); }

private:
  // Angles about a point light measured from the middle of the widest gap between lines, in
  // order: a plane's sides may lie on both sides of the light, and a side across the cut
  // could not be cut at the lines.
  static void from_widest_gap(std::vector<std::pair<double, int>>& lines) {
    const double turn = 2.0 * std::numbers::pi;
    double cut = lines.back().first, widest = lines.front().first + turn - lines.back().first;
    for (size_t k = 0; k + 1 < lines.size(); ++k)
      if (lines[k + 1].first - lines[k].first > widest) {
        widest = lines[k + 1].first - lines[k].first;
        cut = lines[k].first;
      }
    cut += 0.5 * widest;
    for (auto& [angle, line] : lines) angle = std::fmod(angle - cut + 2.0 * turn, turn);
    std::sort(lines.begin(), lines.end());
  }

  bool coplanar(const Side& s, const Side& t) const {
    const glm::dvec3 p = sight_.vertex(s.from), q = sight_.vertex(s.to);
    for (int line : {t.from, t.to})
      if (line != s.from && line != s.to &&
          std::abs(glm::dot(view_.normal(p, q), sight_.vertex(line) - p)) > tolerance_)
        return false;
    return true;
  }

  glm::dvec4 point(int vertex) const { return glm::dvec4(set_.vertex(vertex), 1.0); }

  // Side s where the line of sight `line` crosses it: an end, or a point of its edge.
  glm::dvec4 at(const SidePlane& plane, const Side& s, int line) const {
    if (line == s.from) return point(s.a);
    if (line == s.to) return point(s.b);
    return glm::dvec4(plane.meet(set_.vertex(s.a), set_.vertex(s.b), sight_.vertex(line)), 1.0);
  }

  void sum_across(const SidePlane& plane, const std::vector<std::pair<Side, int>>& sides, int first, int second) {
    struct Cut {
      glm::dvec4 first, second;  // the side at the two lines of sight
      double depth;
      int winding;
    };
    std::vector<Cut> cuts;
    for (const auto& [s, winding] : sides) {
      const glm::dvec4 p = at(plane, s, first), q = at(plane, s, second);
      cuts.push_back({p, q, view_.depth(0.5 * glm::dvec3(p + q)), winding});
    }
    std::sort(cuts.begin(), cuts.end(), [](const Cut& x, const Cut& y) { return x.depth > y.depth; });
    int weight = 0;
    for (size_t j = 0; j < cuts.size(); ++j) {
      weight += cuts[j].winding;
      const Cut& c = cuts[j];
      if (j + 1 == cuts.size()) {
        emit(out_, c.first, c.second, apex_, weight);
        break;
      }
      const Cut& next = cuts[j + 1];
      emit(out_, c.first, c.second, next.second, weight);
      emit(out_, c.first, next.second, next.first, weight);
    }
  }

  const geometry::ConformingSet& set_;
  const geometry::ConformingSet& sight_;
  const LightView& view_;
  glm::dvec4 apex_;
  double tolerance_;
  std::vector<WeightedTriangle>& out_;
};

}  // namespace

std::vector<WeightedTriangle> summed_sides(const geometry::ConformingSet& set, const std::vector<PyramidSide>& sides,
                                           const glm::dvec4& apex, double reach, double tolerance) {
  const LightView view(apex, reach);
  std::vector<geometry::BeamPolygon> seen;
  for (const PyramidSide& s : sides) seen.push_back({{view.seen(set.vertex(s.a)), view.seen(set.vertex(s.b))}});
  const geometry::ConformingSet sight(seen, tolerance);
  std::vector<Side> kept;
  for (size_t k = 0; k < sides.size(); ++k) {
    const std::vector<int>& lines = sight.welded(k);
    if (lines[0] != lines[1])  // else seen end-on from the light: it bounds nothing
      kept.push_back({sides[k].a, sides[k].b, lines[0], lines[1]});
  }
  std::vector<WeightedTriangle> out;
  SideSum sum(set, sight, view, apex, tolerance, out);
  for (const std::vector<Side>& plane : sum.planes(kept)) {
    if (plane.size() == 1) sum.whole(plane[0]);
    else sum.sum(plane);
  }
  return out;
}

}  // namespace airlight::methods
