// glTF 2.0 scenes (docs/scene-format.md "glTF scenes", docs/decisions.md "glTF scenes").
// tinygltf (Debian's libtinygltf) parses the file; everything airlight needs from it is
// checked here, each failure an InputError naming the element ("meshes[0].primitives[1]").
// Section numbers are the glTF 2.0 specification's.
#include "scene/gltf_scene.hpp"

#include "core/warning.hpp"
#include "scene/camera_limits.hpp"
#include "scene/json_reader.hpp"
#include "scene/light_defaults.hpp"
#include "scene/mesh_build.hpp"
#include "scene/scene_parse.hpp"

#include <airlight/error.hpp>
#include <algorithm>
#include <climits>
#include <cmath>
#include <cstring>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <numbers>
#include <set>
#include <tiny_gltf.h>

namespace airlight::scene_gltf {
namespace {

using scene_json::JsonNode;
using scene_json::JsonObject;

std::string indexed(const std::string& array, size_t i) { return array + "[" + std::to_string(i) + "]"; }

// §3.7.2.1: a strip's or a fan's vertices as a list of triangles, each wound as
// the specification orders it (a strip's every other triangle turned back).
std::vector<uint32_t> triangle_list(int mode, std::vector<uint32_t> v) {
  if (mode == TINYGLTF_MODE_TRIANGLES) return v;
  std::vector<uint32_t> list;
  for (size_t i = 0; i + 2 < v.size(); ++i)
    if (mode == TINYGLTF_MODE_TRIANGLE_STRIP)
      list.insert(list.end(), {v[i], v[i + 1 + i % 2], v[i + 2 - i % 2]});
    else  // fan
      list.insert(list.end(), {v[i + 1], v[i + 2], v[0]});
  return list;
}

class Reader {
public:
  Reader(const tinygltf::Model& model, std::string file) : m_(model), file_(std::move(file)) {}

  Scene read() {
    check_required_extensions();
    if (m_.scenes.empty()) fail("scenes", "the file has no scene: nothing to render");
    const size_t s = m_.defaultScene < 0 ? 0 : size_t(m_.defaultScene);
    if (s >= m_.scenes.size()) fail("scene", "refers to " + indexed("scenes", s) + ", which does not exist");
    if (m_.scenes.size() > 1)
      warn(file_, "has " + std::to_string(m_.scenes.size()) + " scenes: rendering " + indexed("scenes", s) +
                      (m_.defaultScene < 0 ? ", the first (the file names no default)" : ", its default"));
    const tinygltf::Scene& scene = m_.scenes[s];
    for (size_t k = 0; k < scene.nodes.size(); ++k)
      visit(checked_index(scene.nodes[k], m_.nodes.size(), indexed(indexed("scenes", s) + ".nodes", k), "nodes"),
            glm::dmat4(1.0));
    check_untriangulated();
    if (!camera_) out_.camera = framing_camera();
    read_extras(scene, indexed("scenes", s) + ".extras");
    return std::move(out_);
  }

private:
  [[noreturn]] void fail(const std::string& key, const std::string& message) const {
    throw InputError(file_, key, message);
  }

  size_t checked_index(int index, size_t size, const std::string& key, const std::string& array) const {
    if (index < 0 || size_t(index) >= size)
      fail(key, "refers to " + array + "[" + std::to_string(index) + "], which does not exist");
    return size_t(index);
  }

  // §3.12: an extension the file requires changes what its data means; airlight reads
  // lights, and material extensions only refine what a Lambertian surface ignores. The
  // others — compressed or quantized geometry (Draco, meshopt, KHR_mesh_quantization)
  // above all — an exporter writes only when asked to.
  void check_required_extensions() const {
    for (size_t i = 0; i < m_.extensionsRequired.size(); ++i) {
      const std::string& name = m_.extensionsRequired[i];
      if (name != "KHR_lights_punctual" && !name.starts_with("KHR_materials_"))
        fail(indexed("extensionsRequired", i),
             "\"" + name + "\" is not supported: export the model again without it (airlight reads "
             "KHR_lights_punctual and ignores KHR_materials_*)");
    }
  }

  // Points and lines (§3.7.2.1) have no area to cast a shadow or end a view ray: they
  // are left out with one warning that counts them, and refused when nothing is left.
  void check_untriangulated() const {
    if (untriangulated_ == 0) return;
    const std::string count = std::to_string(untriangulated_) + " primitive" + (untriangulated_ == 1 ? "" : "s");
    if (out_.meshes.empty()) fail("meshes", "has no triangles, only " + count + " of points or lines");
    warn(file_, "skipped " + count + " of points or lines (airlight renders triangles)");
  }

  // §3.5.3: a node's matrix, or translation · rotation · scale.
  static glm::dmat4 local_matrix(const tinygltf::Node& node) {
    if (node.matrix.size() == 16) return glm::make_mat4(node.matrix.data());  // column-major, as glm
    glm::dmat4 m(1.0);
    if (node.translation.size() == 3) m = glm::translate(m, glm::make_vec3(node.translation.data()));
    if (node.rotation.size() == 4) {
      const auto& r = node.rotation;  // x, y, z, w
      m *= glm::mat4_cast(glm::normalize(glm::dquat(r[3], r[0], r[1], r[2])));
    }
    if (node.scale.size() == 3) m = glm::scale(m, glm::make_vec3(node.scale.data()));
    return m;
  }

  // Depth first, children in order: "the first camera" is the first met this way.
  void visit(size_t n, const glm::dmat4& parent) {
    const std::string key = indexed("nodes", n);
    // §3.5.1: the nodes form disjoint strict trees, so a node is reached once.
    if (!visited_.insert(n).second) fail(key, "is reached twice from the scene (a node has at most one parent)");
    const tinygltf::Node& node = m_.nodes[n];
    const glm::dmat4 world = parent * local_matrix(node);
    for (int i = 0; i < 16; ++i)
      if (!std::isfinite(glm::value_ptr(world)[i])) fail(key, "its transform is not finite");
    if (node.mesh != -1) add_mesh(n, checked_index(node.mesh, m_.meshes.size(), key + ".mesh", "meshes"), world);
    if (node.camera != -1) {
      const size_t c = checked_index(node.camera, m_.cameras.size(), key + ".camera", "cameras");
      if (!camera_) set_camera(c, world);
    }
    const auto light = node.extensions.find("KHR_lights_punctual");
    if (light != node.extensions.end()) add_light(key + ".extensions.KHR_lights_punctual", light->second, world);
    for (size_t k = 0; k < node.children.size(); ++k)
      visit(checked_index(node.children[k], m_.nodes.size(), indexed(key + ".children", k), "nodes"), world);
  }

  // ---- accessors (§3.6.2) ----

  struct View {
    const unsigned char* data;
    size_t stride, count;
  };

  // Accessor `a` checked to hold `count` elements of `components` × componentType in bounds.
  View view_of(size_t a, int components, const std::set<int>& component_types, const std::string& what) const {
    const std::string key = indexed("accessors", a);
    const tinygltf::Accessor& acc = m_.accessors[a];
    if (acc.sparse.isSparse) fail(key, "is sparse, which airlight does not read: export the model again without sparse accessors");
    if (tinygltf::GetNumComponentsInType(uint32_t(acc.type)) != components ||
        !component_types.contains(acc.componentType))
      fail(key, "must be " + what + " (type " + std::to_string(acc.type) + ", componentType " +
                    std::to_string(acc.componentType) + ")");
    const size_t v = checked_index(acc.bufferView, m_.bufferViews.size(), key + ".bufferView", "bufferViews");
    const tinygltf::BufferView& view = m_.bufferViews[v];
    const size_t b = checked_index(view.buffer, m_.buffers.size(), indexed("bufferViews", v) + ".buffer", "buffers");
    const size_t buffer_size = m_.buffers[b].data.size();
    if (view.byteOffset > buffer_size || view.byteLength > buffer_size - view.byteOffset)
      fail(indexed("bufferViews", v), "runs past the end of " + indexed("buffers", b) + " (" +
                                          std::to_string(buffer_size) + " bytes)");
    const int stride = acc.ByteStride(view);
    if (stride <= 0) fail(indexed("bufferViews", v), "has an invalid byteStride");
    const size_t element = size_t(components) * size_t(tinygltf::GetComponentSizeInBytes(uint32_t(acc.componentType)));
    if (acc.count > 0 && (acc.count > view.byteLength || acc.byteOffset > view.byteLength ||
                          (acc.count - 1) * size_t(stride) + element > view.byteLength - acc.byteOffset))
      fail(key, "runs past the end of " + indexed("bufferViews", v));
    return {m_.buffers[b].data.data() + view.byteOffset + acc.byteOffset, size_t(stride), acc.count};
  }

  // A VEC3 FLOAT accessor (POSITION, NORMAL), every element finite.
  std::vector<glm::dvec3> read_vec3(size_t a, const std::string& attribute) const {
    const View v = view_of(a, 3, {TINYGLTF_COMPONENT_TYPE_FLOAT}, "VEC3 of FLOAT for " + attribute);
    std::vector<glm::dvec3> out(v.count);
    for (size_t i = 0; i < v.count; ++i) {
      float f[3];
      std::memcpy(f, v.data + i * v.stride, sizeof f);
      if (!std::isfinite(f[0]) || !std::isfinite(f[1]) || !std::isfinite(f[2]))
        fail(indexed("accessors", a), "element " + std::to_string(i) + " is not finite");
      out[i] = glm::dvec3(f[0], f[1], f[2]);
    }
    return out;
  }

  std::vector<uint32_t> read_indices(size_t a, size_t vertex_count) const {
    const View v = view_of(a, 1,
                           {TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT,
                            TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT},
                           "SCALAR of an unsigned integer type for indices");
    const int size = tinygltf::GetComponentSizeInBytes(uint32_t(m_.accessors[a].componentType));
    std::vector<uint32_t> out(v.count);
    for (size_t i = 0; i < v.count; ++i) {
      const unsigned char* p = v.data + i * v.stride;
      uint32_t index = 0;
      if (size == 1) index = p[0];
      if (size == 2) { uint16_t s; std::memcpy(&s, p, 2); index = s; }
      if (size == 4) std::memcpy(&index, p, 4);
      if (index >= vertex_count)
        fail(indexed("accessors", a), "element " + std::to_string(i) + " is " + std::to_string(index) +
                                          ", past the last of " + std::to_string(vertex_count) + " vertices");
      out[i] = index;
    }
    return out;
  }

  // ---- meshes (§3.7) ----

  // §3.9.2: baseColorFactor is the Lambertian albedo here; textures are ignored. Without a
  // material the default material's white applies (§3.9.6).
  Color albedo(int material, const std::string& key) const {
    if (material == -1) return Color(1.0f);
    const size_t i = checked_index(material, m_.materials.size(), key, "materials");
    const auto& f = m_.materials[i].pbrMetallicRoughness.baseColorFactor;
    if (f.size() != 4) fail(indexed("materials", i) + ".pbrMetallicRoughness.baseColorFactor", "must have 4 numbers");
    return glm::clamp(Color(float(f[0]), float(f[1]), float(f[2])), 0.0f, 1.0f);
  }

  void add_mesh(size_t n, size_t mesh_index, const glm::dmat4& world) {
    const tinygltf::Mesh& mesh = m_.meshes[mesh_index];
    const glm::dmat3 linear(world);
    // A zero scale hides a node (§3.5.3 allows it): nothing of it is drawn.
    if (glm::determinant(linear) == 0.0) return;
    const glm::dmat3 normal_matrix = glm::transpose(glm::inverse(linear));
    // §3.7.2.1: a transform with a negative determinant turns counter-clockwise faces clockwise.
    const bool flip = glm::determinant(linear) < 0.0;
    const std::string& name = m_.nodes[n].name.empty() ? mesh.name : m_.nodes[n].name;
    const std::string label = indexed("nodes", n) + (name.empty() ? "" : " (" + name + ")");
    for (size_t p = 0; p < mesh.primitives.size(); ++p) {
      const std::string key = indexed(indexed("meshes", mesh_index) + ".primitives", p);
      const tinygltf::Primitive& prim = mesh.primitives[p];
      if (prim.mode >= TINYGLTF_MODE_POINTS && prim.mode <= TINYGLTF_MODE_LINE_STRIP) {
        ++untriangulated_;
        continue;
      }
      if (prim.mode < TINYGLTF_MODE_TRIANGLES || prim.mode > TINYGLTF_MODE_TRIANGLE_FAN)
        fail(key, "mode " + std::to_string(prim.mode) + " is not a glTF primitive mode");
      const auto position = prim.attributes.find("POSITION");
      if (position == prim.attributes.end()) fail(key, "has no POSITION attribute");
      const size_t position_accessor =
          checked_index(position->second, m_.accessors.size(), key + ".attributes.POSITION", "accessors");
      std::vector<glm::dvec3> positions = read_vec3(position_accessor, "POSITION");
      std::vector<uint32_t> indices(positions.size());
      if (prim.indices != -1)
        indices = read_indices(checked_index(prim.indices, m_.accessors.size(), key + ".indices", "accessors"),
                               positions.size());
      else
        for (uint32_t i = 0; i < indices.size(); ++i) indices[i] = i;
      indices = triangle_list(prim.mode, std::move(indices));
      if (indices.size() % 3 != 0) fail(key, "has " + std::to_string(indices.size()) + " indices, not a multiple of 3");
      for (glm::dvec3& q : positions) q = glm::dvec3(world * glm::dvec4(q, 1.0));

      Mesh out;
      size_t skipped = 0;
      const auto normal = prim.attributes.find("NORMAL");
      if (normal != prim.attributes.end()) {
        const size_t a = checked_index(normal->second, m_.accessors.size(), key + ".attributes.NORMAL", "accessors");
        const std::vector<glm::dvec3> normals = read_vec3(a, "NORMAL");
        if (normals.size() != positions.size()) fail(indexed("accessors", a), "must have as many elements as POSITION");
        for (size_t i = 0; i < positions.size(); ++i) {
          const glm::dvec3 nw = normal_matrix * normals[i];
          if (!(glm::length(nw) > 1e-12))
            fail(indexed("accessors", a), "element " + std::to_string(i) + " has zero length");
          out.positions.push_back(glm::vec3(positions[i]));
          out.normals.push_back(glm::vec3(glm::normalize(nw)));
        }
        for (size_t t = 0; t < indices.size(); t += 3) {
          glm::uvec3 tri(indices[t], indices[t + 1], indices[t + 2]);
          if (flip) std::swap(tri.y, tri.z);
          if (scene_mesh::is_degenerate(out.positions[tri.x], out.positions[tri.y], out.positions[tri.z]))
            ++skipped;
          else
            out.triangles.push_back(tri);
        }
      } else {
        // §3.7.2.1: without normals, flat ones.
        scene_mesh::MeshBuilder b;
        for (size_t t = 0; t < indices.size(); t += 3) {
          glm::vec3 c[3] = {glm::vec3(positions[indices[t]]), glm::vec3(positions[indices[t + 1]]),
                            glm::vec3(positions[indices[t + 2]])};
          if (flip) std::swap(c[1], c[2]);
          if (scene_mesh::is_degenerate(c[0], c[1], c[2])) {
            ++skipped;
            continue;
          }
          const glm::vec3 f = scene_mesh::face_normal(c[0], c[1], c[2]);
          const uint32_t first = b.vertex(c[0], f);
          b.vertex(c[1], f);
          b.vertex(c[2], f);
          b.triangle(first, first + 1, first + 2);
        }
        out = b.take("");
      }
      if (out.triangles.empty()) fail(key, "has no triangle of non-zero area");
      // As an OBJ's: exported meshes hold slivers; one warning counts them.
      if (skipped > 0)
        warn(file_, key + ": skipped " + std::to_string(skipped) + " degenerate triangle" + (skipped == 1 ? "" : "s") +
                        " (zero area)");
      out.albedo = albedo(prim.material, key + ".material");
      out.name = label + (mesh.primitives.size() > 1 ? " primitive " + std::to_string(p) : "");
      out_.meshes.push_back(std::move(out));
      triangles_.add(out_.meshes.back(), file_, key);
    }
  }

  // ---- cameras (§3.10) and lights (KHR_lights_punctual) ----

  // A camera looks down its node's −Z with +Y up (§3.10.1), as a light points down −Z.
  glm::dvec3 node_axis(const glm::dmat4& world, const glm::dvec3& local, const std::string& key) const {
    const glm::dvec3 axis = glm::dmat3(world) * local;
    if (!(glm::length(axis) > 1e-12)) fail(key, "its node's transform has a zero scale: it has no direction");
    return glm::normalize(axis);
  }

  void set_camera(size_t c, const glm::dmat4& world) {
    const std::string key = indexed("cameras", c);
    const tinygltf::Camera& cam = m_.cameras[c];
    if (cam.type != "perspective") fail(key, "is " + cam.type + ": airlight renders perspective cameras only");
    const tinygltf::PerspectiveCamera& p = cam.perspective;
    if (!(p.yfov > 0.0 && p.yfov < std::numbers::pi)) fail(key + ".perspective.yfov", "must be in (0, pi)");
    if (!(p.znear > 0.0)) fail(key + ".perspective.znear", "must be > 0");
    Camera camera;
    camera.position = glm::vec3(world * glm::dvec4(0, 0, 0, 1));
    camera.look_at = camera.position + glm::vec3(node_axis(world, {0, 0, -1}, key));
    camera.up = glm::vec3(node_axis(world, {0, 1, 0}, key));
    camera.fov_y_deg = float(p.yfov * 180.0 / std::numbers::pi);
    camera.near = float(p.znear);
    if (p.zfar > 0.0) camera.far = float(p.zfar);  // 0: infinite in tinygltf; airlight's default then
    if (!(camera.far > camera.near)) fail(key + ".perspective.zfar", "must be greater than znear");
    if (const std::string problem = scene_camera::depth_range_problem(camera); !problem.empty())
      fail(key + ".perspective.zfar", problem);
    out_.camera = camera;
    camera_ = true;
  }

  // No camera in the scene: one looking at the sphere around the meshes' bounding box from
  // the front (+Z, §3.4: "the front of a glTF asset faces +Z") and a little above, the
  // sphere filling the default 45° field of view.
  Camera framing_camera() const {
    Camera camera;
    if (out_.meshes.empty()) return camera;
    glm::vec3 lo(INFINITY), hi(-INFINITY);
    for (const Mesh& mesh : out_.meshes)
      for (const glm::vec3& p : mesh.positions) lo = glm::min(lo, p), hi = glm::max(hi, p);
    const glm::vec3 centre = 0.5f * (lo + hi);
    const float radius = std::max(0.5f * glm::length(hi - lo), 1e-3f);
    const float distance = radius / std::sin(glm::radians(0.5f * camera.fov_y_deg));
    camera.look_at = centre;
    camera.position = centre + distance * glm::normalize(glm::vec3(0, 0.5f, 1));
    camera.far = std::max(camera.far, distance + 2.0f * radius);
    // Far enough for a large model would leave the default near past the depth range airlight
    // supports; a hair inside the limit, since far/limit rounds to float.
    camera.near = std::max(camera.near, camera.far / float(0.999 * max_far_over_near));
    return camera;
  }

  void add_light(const std::string& node_key, const tinygltf::Value& extension, const glm::dmat4& world) {
    const tinygltf::Value& index = extension.Get("light");
    if (!index.IsNumber()) fail(node_key + ".light", "must be the index of a light");
    const std::string key = "extensions.KHR_lights_punctual.lights";
    const size_t i = checked_index(index.GetNumberAsInt(), m_.lights.size(), node_key + ".light", key);
    const tinygltf::Light& l = m_.lights[i];
    const std::string lkey = indexed(key, i);
    Color color(1.0f);
    if (!l.color.empty()) {
      if (l.color.size() != 3) fail(lkey + ".color", "must have 3 numbers");
      color = Color(float(l.color[0]), float(l.color[1]), float(l.color[2]));
      if (!std::isfinite(color.r + color.g + color.b) || glm::any(glm::lessThan(color, Color(0.0f))))
        fail(lkey + ".color", "must be finite and >= 0");
    }
    if (!(l.intensity >= 0.0 && std::isfinite(l.intensity))) fail(lkey + ".intensity", "must be finite and >= 0");
    // Candela (lm/sr) and lux (lm/m²) to W/sr and W/m²; the colour multiplies (the
    // extension: intensity is that of the light were it white).
    const Color radiometric = color * float(l.intensity / lumens_per_watt);
    Light light;
    light.position = glm::vec3(world * glm::dvec4(0, 0, 0, 1));
    if (l.type == "spot" || l.type == "directional") {
      light.direction = glm::vec3(node_axis(world, {0, 0, -1}, lkey));
      light.gobo_up = scene_light::default_gobo_up(light.direction);
    }
    if (l.type == "point") {
      light.type = LightType::point;
      light.intensity = radiometric;
    } else if (l.type == "spot") {
      light.type = LightType::spot;
      light.intensity = radiometric;
      const double inner = l.spot.innerConeAngle, outer = l.spot.outerConeAngle;
      if (!(outer > 0.0 && outer <= std::numbers::pi / 2)) fail(lkey + ".spot.outerConeAngle", "must be in (0, pi/2]");
      if (!(inner >= 0.0 && inner < outer)) fail(lkey + ".spot.innerConeAngle", "must be in [0, outerConeAngle)");
      const SpotCone cone = spot_cone(inner, outer);
      light.cone_deg = cone.cone_deg;
      light.edge_deg = cone.edge_deg;
    } else if (l.type == "directional") {
      light.type = LightType::directional;
      light.irradiance = radiometric;
    } else {
      fail(lkey + ".type", "must be \"point\", \"spot\" or \"directional\", not \"" + l.type + "\"");
    }
    out_.lights.push_back(light);
  }

  // ---- fog ----

  // The scene's extras.airlight: the fog keys of a scene file. Other extras belong to
  // other tools (Blender writes every custom property there) and are left alone.
  void read_extras(const tinygltf::Scene& scene, const std::string& key) {
    if (scene.extras_json_string.empty()) return;
    const scene_json::Json json = scene_json::parse_json_text(scene.extras_json_string, file_);
    if (!json.is_object() || !json.contains("airlight")) return;
    const JsonNode extras(json, file_, key);
    const JsonNode airlight(json.at("airlight"), file_, extras.member_key("airlight"));
    JsonObject fog(airlight);
    scene_json::read_fog(fog, out_);
    fog.finish();
  }

  const tinygltf::Model& m_;
  std::string file_;
  Scene out_;
  bool camera_ = false;
  std::set<size_t> visited_;
  size_t untriangulated_ = 0;  // primitives of points or lines, left out
  scene_mesh::TriangleCount triangles_;
};

// The files a glTF names (its buffers, its images) are read from its own folder or
// below it, never from ../ or an absolute path: a model from the web must not make
// airlight read other files. Paths are taken as written: no shell expansion, which
// tinygltf's own ExpandFilePath does (wordexp).
struct Folder {
  std::filesystem::path root;  // the glTF's folder, absolute and normal
  const FileSource& files;
  std::string outside;         // the first path refused, relative to root
};

bool inside(Folder& folder, const std::string& path) {
  const std::filesystem::path relative =
      std::filesystem::absolute(path).lexically_normal().lexically_relative(folder.root);
  if (!relative.empty() && *relative.begin() != "..") return true;
  if (folder.outside.empty()) folder.outside = relative.empty() ? path : relative.string();
  return false;
}

bool file_exists(const std::string& path, void* data) {
  Folder& folder = *static_cast<Folder*>(data);
  return inside(folder, path) && folder.files.exists(path);
}

std::string expand_path(const std::string& path, void*) { return path; }

bool read_file(std::vector<unsigned char>* out, std::string* error, const std::string& path, void* data) {
  Folder& folder = *static_cast<Folder*>(data);
  if (!inside(folder, path)) return false;
  try {
    const std::string bytes = folder.files.read(path);
    out->assign(bytes.begin(), bytes.end());
    return true;
  } catch (const InputError& e) {
    *error += e.what();
    return false;
  }
}

bool write_file(std::string*, const std::string&, const std::vector<unsigned char>&, void*) { return false; }

// Images play no part: none is decoded.
bool skip_image(tinygltf::Image*, const int, std::string*, std::string*, int, int, const unsigned char*, int, void*) {
  return true;
}

// tinygltf's messages end in newlines and may hold several lines; a JSON syntax error
// carries nlohmann's "[json.exception.parse_error.101] ", which says nothing to a user.
std::string plain(std::string text) {
  while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.pop_back();
  std::replace(text.begin(), text.end(), '\n', ' ');
  const size_t id = text.find("[json.exception."), end = text.find("] ", id);
  if (id != std::string::npos && end != std::string::npos) text.erase(id, end + 2 - id);
  return text;
}

// tinygltf copies the JSON into its own values by recursion, a level a call: a text
// nested thousands deep overflows the stack (docs/decisions.md "Fuzzing"). No glTF
// needs more than a dozen levels; extras may hold a few more.
constexpr int max_json_depth = 100;

// The JSON text of a .gltf, or of a .glb's first chunk (its JSON; header §4.4.3).
std::string_view json_text(const std::string& bytes, bool glb) {
  if (!glb) return bytes;
  if (bytes.size() < 20) return {};
  std::uint32_t length = 0;
  std::memcpy(&length, bytes.data() + 12, 4);
  return std::string_view(bytes).substr(20, length);
}

void check_depth(std::string_view json, const std::string& file) {
  int depth = 0;
  bool in_string = false;
  for (size_t i = 0; i < json.size(); ++i) {
    const char c = json[i];
    if (in_string) {
      if (c == '\\') ++i;
      in_string = c != '"';
    } else if (c == '"') {
      in_string = true;
    } else if (c == '[' || c == '{') {
      if (++depth > max_json_depth)
        throw InputError(file, "", "the JSON nests deeper than " + std::to_string(max_json_depth) + " levels");
    } else if (c == ']' || c == '}') {
      --depth;
    }
  }
}

}  // namespace

SpotCone spot_cone(double inner_cone_angle, double outer_cone_angle) {
  const double degrees = 180.0 / std::numbers::pi;
  return {float(outer_cone_angle * degrees), float((outer_cone_angle - inner_cone_angle) * degrees)};
}

bool is_gltf_file(const std::filesystem::path& file) {
  std::string ext = file.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return ext == ".gltf" || ext == ".glb";
}

Scene load_gltf(const std::filesystem::path& file, const FileSource& files) {
  tinygltf::TinyGLTF loader;
  loader.SetImageLoader(skip_image, nullptr);
  Folder folder{std::filesystem::absolute(file).parent_path().lexically_normal(), files, ""};
  loader.SetFsCallbacks({file_exists, expand_path, read_file, write_file, &folder});
  loader.SetStoreOriginalJSONForExtrasAndExtensions(true);
  tinygltf::Model model;
  std::string error, warning;  // warnings concern what airlight ignores (images, unknown extensions)
  std::string ext = file.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  const std::string bytes = files.read(file);
  check_depth(json_text(bytes, ext == ".glb"), file.string());
  const auto size = static_cast<unsigned int>(std::min<size_t>(bytes.size(), UINT_MAX));
  const bool ok = ext == ".glb"
                      ? loader.LoadBinaryFromMemory(&model, &error, &warning,
                                                    reinterpret_cast<const unsigned char*>(bytes.data()), size,
                                                    folder.root.string())
                      : loader.LoadASCIIFromString(&model, &error, &warning, bytes.data(), size, folder.root.string());
  if (!folder.outside.empty())
    throw InputError(file.string(), "uri",
                     "\"" + folder.outside + "\" is outside the file's folder: airlight reads only the files "
                     "beside a glTF or in folders below it");
  if (!ok) throw InputError(file.string(), "", "not a valid glTF file: " + plain(error));
  Scene scene = Reader(model, file.string()).read();
  scene.source = file;
  scene.name = file.stem().string();
  return scene;
}

}  // namespace airlight::scene_gltf
