#include "methods.hpp"

namespace airlight::fuzz {
namespace {

using T = SettingSpec::Type;

std::vector<SettingSpec> shadow_settings() {
  return {{"shadow_resolution", T::integer, 1024, 64, 8192, {}, ""}, {"shadow_bias", T::real, 1, 0, 16, {}, ""}};
}

MethodInfo method(const std::string& name, std::vector<SettingSpec> own) {
  MethodInfo info;
  info.name = name;
  info.settings = shadow_settings();
  info.settings.insert(info.settings.end(), own.begin(), own.end());
  return info;
}

}  // namespace

MethodInfo reference_info() {
  MethodInfo info;
  info.name = "reference";
  info.capabilities.ground_truth = true;
  info.settings = {{"rel_tol", T::real, 1e-3, 1e-7, 0.1, {}, ""}, {"min_segments", T::integer, 128, 1, 4096, {}, ""}};
  return info;
}

MethodInfo raymarch_info() {
  return method("raymarch", {{"steps", T::integer, 64, 1, 4096, {}, ""},
                             {"jitter", T::choice, 0, 0, 0, {"none", "white", "blue"}, ""},
                             {"sampling", T::choice, 1, 0, 0, {"uniform", "equiangular"}, ""},
                             {"scale", T::choice, 0, 0, 0, {"1", "1/2", "1/4"}, ""},
                             {"upsample", T::choice, 0, 0, 0, {"bilateral", "bilinear"}, ""}});
}

MethodInfo planes_info() {
  return method("planes", {{"planes", T::integer, 100, 1, 8192, {}, ""},
                           {"spacing", T::real, 0, 0, 100, {}, ""},
                           {"lattice", T::integer, 0, 0, 512, {}, ""},
                           {"jitter", T::choice, 0, 0, 0, {"none", "white", "blue"}, ""},
                           {"sampling", T::choice, 0, 0, 0, {"lit", "plane"}, ""},
                           {"clip", T::boolean, 1, 0, 1, {}, ""}});
}

}  // namespace airlight::fuzz
