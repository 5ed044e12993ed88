// Shared by the GLSL twin tests (optics_twin_test.cpp, cone_twin_test.cpp): run a
// twin shader over thousands of inputs, and collect and report its errors.
// The C++ works in double, the twins in float: "ε" below is 2^-24 ≈ 6e-8.
#pragma once
#include "gpu/context.hpp"
#include "gpu/program.hpp"
#include "optics/closed_form.hpp"
#include "optics/cone_test_cases.hpp"
#include "optics/light.hpp"
#include "optics/media.hpp"
#include "optics/phase.hpp"

#include <airlight/scene.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <glm/geometric.hpp>
#include <glm/vec4.hpp>
#include <map>
#include <memory>
#include <numbers>
#include <random>
#include <string>
#include <vector>

namespace airlight::kit::twin {

using namespace airlight::gpu;


inline constexpr double pi = std::numbers::pi;

// Runs methods/kit/testing/twins/shaders/<shader> over inputs.size() / in_stride cases (the
// layout of twin_io.glsl) and returns out_stride vec4s per case. `defines`
// are prepended to the shader; `binding` is its TWIN_BINDING (twin_io.glsl).
inline std::vector<glm::vec4> run_twin(const std::string& shader, const std::vector<glm::vec4>& inputs,
                                int in_stride, int out_stride, const std::string& defines = "",
                                GLuint binding = 0) {
  Context& context = Context::headless();
  const Program program = make_compute_program("methods/kit/testing/twins/shaders/" + shader, defines);
  const int count = static_cast<int>(inputs.size()) / in_stride;
  const Buffer in = make_buffer(inputs.size() * sizeof(glm::vec4), inputs.data());
  const size_t out_bytes = static_cast<size_t>(count) * out_stride * sizeof(glm::vec4);
  const Buffer out = make_buffer(out_bytes, nullptr);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding, in.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding + 1, out.id());
  glUseProgram(program.id());
  set_uniform(program, "count", count);
  glDispatchCompute((count + 63) / 64, 1, 1);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  std::vector<glm::vec4> outputs(static_cast<size_t>(count) * out_stride);
  glGetNamedBufferSubData(out.id(), 0, static_cast<GLsizeiptr>(out_bytes), outputs.data());
  context.check("twin " + shader);
  return outputs;
}

// Checks one function case by case and reports its worst errors (relative ones
// only for functions whose relative error means something: not for chords,
// coordinates or step-like factors). Failures print the case (the first few
// only, so a broken twin doesn't flood the log).
class Errors {
public:
  explicit Errors(std::string name, bool relative = true) : name_(std::move(name)), relative_(relative) {}
  ~Errors() {
    std::printf("%-20s %5d cases (%5d compared)  max abs %-9.3g", name_.c_str(), cases_, compared_, max_abs_);
    if (relative_) std::printf("  max rel %.3g", max_rel_);
    std::printf("\n");
  }

  // Requires a finite gpu value with |gpu - cpu| <= tolerance.
  template <typename Describe>
  void check(double gpu, double cpu, double tolerance, Describe&& describe) {
    if (!finite(gpu, describe)) return;
    ++compared_;
    const double err = std::abs(gpu - cpu);
    max_abs_ = std::max(max_abs_, err);
    if (cpu != 0.0) max_rel_ = std::max(max_rel_, err / std::abs(cpu));
    if (!(err <= tolerance)) fail(describe, "gpu " + std::to_string(gpu) + " cpu " + std::to_string(cpu) +
                                                " tolerance " + std::to_string(tolerance));
  }

  // Only requires a finite gpu value: where the C++ is no reference (stated at the call).
  template <typename Describe>
  bool finite(double gpu, Describe&& describe) {
    ++cases_;
    if (!std::isfinite(gpu)) fail(describe, "non-finite gpu value " + std::to_string(gpu));
    return std::isfinite(gpu);
  }

private:
  template <typename Describe>
  void fail(Describe&& describe, const std::string& what) {
    if (++failures_ <= 8) ADD_FAILURE() << name_ << ": " << what << " at " << describe();
  }

  std::string name_;
  bool relative_;
  int cases_ = 0, compared_ = 0, failures_ = 0;
  double max_abs_ = 0.0, max_rel_ = 0.0;
};

inline std::string str(const glm::vec3& v) {
  return "(" + std::to_string(v.x) + ", " + std::to_string(v.y) + ", " + std::to_string(v.z) + ")";
}

inline glm::vec3 random_unit(std::mt19937& rng) {
  std::normal_distribution<float> n;
  for (;;) {
    const glm::vec3 v(n(rng), n(rng), n(rng));
    if (glm::dot(v, v) > 1e-6f) return glm::normalize(v);
  }
}

inline float uniform(std::mt19937& rng, float lo, float hi) { return std::uniform_real_distribution<float>(lo, hi)(rng); }

// A 12 m square floor at y = -1: something for the frame's passes to draw.
inline Mesh floor_mesh() {
  Mesh floor;
  floor.positions = {{-6, -1, 6}, {6, -1, 6}, {6, -1, -6}, {-6, -1, -6}};
  floor.normals.assign(4, {0, 1, 0});
  floor.triangles = {{0, 1, 2}, {0, 2, 3}};
  return floor;
}

}  // namespace airlight::kit::twin
