#pragma once
// The differential harness (docs/design.md §6): a scene rendered by the
// reference and by each method, at its defaults and in each of its trials, every
// image judged (harness/judge.hpp); a failure shrunk to the smallest scene that
// still fails it.
#include "harness/judge.hpp"

#include <airlight/method.hpp>
#include <airlight/scene.hpp>

#include <string>
#include <vector>

namespace airlight::harness {

inline bool fails(const Verdict& v) { return !v.pass; }

struct Judgement {
  std::string method;
  Verdict verdict;
  double seconds = 0.0;  // prepare and render
};

struct Outcome {
  double reference_mean = 0.0;  // the full reference's mean airlight
  bool visible = true;          // false: rejected (mean below visible_mean), nothing judged
  std::vector<Judgement> judgements;
};

class Harness {
public:
  Harness(std::vector<const MethodInfo*> methods, int width, int height);

  // A scene without lights is always judged (every method must give zero).
  Outcome judge(const Scene& scene) const;
  // One method in one trial ("defaults" or a trial's name) on `scene`.
  Verdict judge(const Scene& scene, const MethodInfo& method, const std::string& trial) const;
  // The scene with lights, meshes and volumes dropped one at a time while the
  // method still fails the trial on it: what a reproduction needs.
  Scene shrink(Scene scene, const MethodInfo& method, const std::string& trial) const;

private:
  Reference reference(const Scene& scene, const Capabilities& capabilities) const;
  Image airlight(const Scene& scene, const MethodInfo& method, const std::vector<std::string>& settings,
                 const std::string& origin) const;
  Verdict judge(const Scene& scene, const MethodInfo& method, const Trial* trial, const Reference& reference,
                double* seconds) const;

  std::vector<const MethodInfo*> methods_;
  int width_, height_;
};

}  // namespace airlight::harness
