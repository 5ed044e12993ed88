#include "reference/ray_caster.hpp"

#include <airlight/error.hpp>
#include <algorithm>
#include <cmath>
#include <embree3/rtcore.h>
#include <glm/geometric.hpp>
#include <limits>
#include <mutex>
#include <string>

namespace airlight::reference {
namespace {

struct DeviceRelease {
  void operator()(RTCDevice device) const { rtcReleaseDevice(device); }
};
struct SceneRelease {
  void operator()(RTCScene scene) const { rtcReleaseScene(scene); }
};
struct GeometryRelease {
  void operator()(RTCGeometry geometry) const { rtcReleaseGeometry(geometry); }
};
using DevicePtr = std::unique_ptr<RTCDeviceTy, DeviceRelease>;
using ScenePtr = std::unique_ptr<RTCSceneTy, SceneRelease>;
using GeometryPtr = std::unique_ptr<RTCGeometryTy, GeometryRelease>;

const char* error_name(RTCError code) {
  switch (code) {
    case RTC_ERROR_NONE: return "no error";
    case RTC_ERROR_INVALID_ARGUMENT: return "invalid argument";
    case RTC_ERROR_INVALID_OPERATION: return "invalid operation";
    case RTC_ERROR_OUT_OF_MEMORY: return "out of memory";
    case RTC_ERROR_UNSUPPORTED_CPU: return "unsupported CPU";
    case RTC_ERROR_CANCELLED: return "cancelled";
    default: return "unknown error";
  }
}

// Collects Embree's messages; the callback may run on Embree's worker threads.
class ErrorLog {
public:
  static void record(void* self, RTCError code, const char* message) {
    auto& log = *static_cast<ErrorLog*>(self);
    const std::lock_guard lock(log.mutex_);
    log.message_ = std::string(error_name(code)) + (message ? std::string(": ") + message : "");
  }
  // Throws Failure with Embree's last message if the device reports an error.
  void check(RTCDevice device, const std::string& what) {
    const RTCError code = rtcGetDeviceError(device);
    if (code == RTC_ERROR_NONE) return;
    const std::lock_guard lock(mutex_);
    throw Failure("Embree: " + what + ": " + (message_.empty() ? error_name(code) : message_));
  }

private:
  std::mutex mutex_;
  std::string message_;
};

// Embree's single-precision rays: positions and directions in float.
void set_ray(RTCRay& ray, const glm::dvec3& origin, const glm::dvec3& dir, double t_near, double t_far) {
  ray.org_x = static_cast<float>(origin.x);
  ray.org_y = static_cast<float>(origin.y);
  ray.org_z = static_cast<float>(origin.z);
  ray.dir_x = static_cast<float>(dir.x);
  ray.dir_y = static_cast<float>(dir.y);
  ray.dir_z = static_cast<float>(dir.z);
  ray.tnear = static_cast<float>(t_near);
  ray.tfar = static_cast<float>(std::min(t_far, static_cast<double>(std::numeric_limits<float>::infinity())));
  ray.time = 0.0f;
  ray.mask = ~0u;
  ray.id = 0;
  ray.flags = 0;
}

void validate(const Mesh& mesh) {
  for (const glm::vec3& p : mesh.positions)
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
      throw Failure("reference: mesh " + mesh.name + ": non-finite vertex position");
  for (const glm::uvec3& tri : mesh.triangles)
    if (tri.x >= mesh.positions.size() || tri.y >= mesh.positions.size() || tri.z >= mesh.positions.size())
      throw Failure("reference: mesh " + mesh.name + ": triangle index out of range");
}

template <typename T>
T* new_buffer(RTCGeometry geometry, RTCBufferType type, RTCFormat format, size_t count) {
  return static_cast<T*>(rtcSetNewGeometryBuffer(geometry, type, 0, format, 3 * sizeof(T), count));
}

}  // namespace

struct RayCaster::Embree {
  std::unique_ptr<ErrorLog> log = std::make_unique<ErrorLog>();  // outlives the device
  DevicePtr device;
  ScenePtr scene;
  ScenePtr casters;  // the meshes that cast shadows, when some do not (Mesh::casts_shadows)
  RTCScene shadow_scene() const { return casters ? casters.get() : scene.get(); }
};

namespace {

void attach_mesh(RTCDevice device, ErrorLog& log, RTCScene scene, const Mesh& mesh, unsigned id) {
  validate(mesh);
  const GeometryPtr geometry(rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE));
  auto* vertices = new_buffer<float>(geometry.get(), RTC_BUFFER_TYPE_VERTEX, RTC_FORMAT_FLOAT3,
                                     mesh.positions.size());
  auto* indices = new_buffer<unsigned>(geometry.get(), RTC_BUFFER_TYPE_INDEX, RTC_FORMAT_UINT3,
                                       mesh.triangles.size());
  log.check(device, "mesh " + mesh.name);
  for (size_t k = 0; k < mesh.positions.size(); ++k)
    for (int c = 0; c < 3; ++c) vertices[3 * k + c] = mesh.positions[k][c];
  for (size_t k = 0; k < mesh.triangles.size(); ++k)
    for (int c = 0; c < 3; ++c) indices[3 * k + c] = mesh.triangles[k][c];
  rtcCommitGeometry(geometry.get());
  rtcAttachGeometryByID(scene, geometry.get(), id);
  log.check(device, "mesh " + mesh.name);
}

}  // namespace

namespace {

// An Embree scene of the meshes `include` accepts, geometry id = mesh index.
template <typename Include>
ScenePtr build_scene(RTCDevice device, ErrorLog& log, const Scene& scene, Include include) {
  ScenePtr built(rtcNewScene(device));
  log.check(device, "new scene");
  rtcSetSceneFlags(built.get(), RTC_SCENE_FLAG_ROBUST);
  rtcSetSceneBuildQuality(built.get(), RTC_BUILD_QUALITY_HIGH);
  for (size_t id = 0; id < scene.meshes.size(); ++id)
    if (!scene.meshes[id].triangles.empty() && include(scene.meshes[id]))
      attach_mesh(device, log, built.get(), scene.meshes[id], static_cast<unsigned>(id));
  rtcCommitScene(built.get());
  log.check(device, "scene build");
  return built;
}

}  // namespace

RayCaster::RayCaster(const Scene& scene) : embree_(std::make_unique<Embree>()) {
  Embree& e = *embree_;
  e.device.reset(rtcNewDevice(nullptr));
  if (!e.device)
    throw Failure(std::string("Embree: cannot create a device: ") + error_name(rtcGetDeviceError(nullptr)));
  rtcSetDeviceErrorFunction(e.device.get(), &ErrorLog::record, e.log.get());
  e.scene = build_scene(e.device.get(), *e.log, scene, [](const Mesh&) { return true; });
  if (std::any_of(scene.meshes.begin(), scene.meshes.end(), [](const Mesh& m) { return !m.casts_shadows; }))
    e.casters = build_scene(e.device.get(), *e.log, scene, [](const Mesh& m) { return m.casts_shadows; });
}

RayCaster::~RayCaster() = default;
RayCaster::RayCaster(RayCaster&&) noexcept = default;
RayCaster& RayCaster::operator=(RayCaster&&) noexcept = default;

std::optional<Hit> RayCaster::intersect(const optics::Ray& ray, double t_near, double t_far) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRayHit query{};
  set_ray(query.ray, ray.origin, ray.dir, t_near, t_far);
  query.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(embree_->scene.get(), &context, &query);
  if (query.hit.geomID == RTC_INVALID_GEOMETRY_ID) return std::nullopt;
  const glm::dvec3 ng(query.hit.Ng_x, query.hit.Ng_y, query.hit.Ng_z);
  const double length = glm::length(ng);
  return Hit{query.ray.tfar, query.hit.geomID, query.hit.primID, query.hit.u, query.hit.v,
             length > 0.0 ? ng / length : -ray.dir};
}

bool RayCaster::occluded(const glm::dvec3& origin, const glm::dvec3& dir, double t_near,
                         double t_far) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRay query{};
  set_ray(query, origin, dir, t_near, t_far);
  rtcOccluded1(embree_->shadow_scene(), &context, &query);
  return query.tfar < 0.0f;  // Embree sets tfar = -inf when the ray is blocked
}

}  // namespace airlight::reference
