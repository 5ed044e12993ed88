#include "core/solid.hpp"
#include "core/warning.hpp"
#include "scene/shapes.hpp"
#include "scene/test_support.hpp"

#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <sstream>

namespace airlight {
namespace {

using namespace scene_mesh;
using scene_test::data_dir;
using scene_test::misoriented_fraction;
using scene_test::signed_volume;
using scene_test::throws_input_error;
using scene_test::well_formed;

std::filesystem::path write_obj(const std::string& name, const std::string& text) {
  const auto dir = std::filesystem::path(::testing::TempDir()) / "airlight_obj_mesh_test";
  std::filesystem::create_directories(dir);
  std::ofstream(dir / name) << text;
  return dir / name;
}

// The mesh's positions and triangles as OBJ text: "v" lines, then "f" lines.
std::string obj_text(const Mesh& mesh) {
  std::ostringstream text;
  for (const glm::vec3& p : mesh.positions) text << "v " << p.x << " " << p.y << " " << p.z << "\n";
  for (const glm::uvec3& t : mesh.triangles) text << "f " << t.x + 1 << " " << t.y + 1 << " " << t.z + 1 << "\n";
  return text.str();
}

using Warnings = CapturedWarnings;

TEST(ObjMesh, LoadsQuadsAsTrianglesWithSmoothNormals) {
  const Mesh cube = load_obj(data_dir() / "cube.obj");
  ASSERT_TRUE(well_formed(cube));
  EXPECT_EQ(cube.name, "cube.obj");
  EXPECT_EQ(cube.positions.size(), 8u);  // no normals in the file: corners are shared
  EXPECT_EQ(cube.triangles.size(), 12u);
  EXPECT_EQ(misoriented_fraction(cube), 0.0);
  EXPECT_NEAR(signed_volume(cube), 1.0, 1e-6);
  // A corner's smooth normal points out along the diagonal.
  for (size_t i = 0; i < cube.positions.size(); ++i) {
    const glm::vec3 out = glm::normalize(cube.positions[i] - glm::vec3(0.5f));
    EXPECT_GT(glm::dot(cube.normals[i], out), 0.99f);
  }
}

TEST(ObjMesh, KeepsTheFilesNormalsNormalized) {
  const Mesh square = load_obj(data_dir() / "normals.obj");
  ASSERT_TRUE(well_formed(square));
  EXPECT_EQ(square.triangles.size(), 2u);
  for (const glm::vec3& n : square.normals) EXPECT_EQ(n, glm::vec3(0, 1, 0));
}

TEST(ObjMesh, DegenerateTriangleIsSkippedWithAWarning) {
  const auto file = data_dir() / "degenerate.obj";
  const Warnings warnings;
  const Mesh mesh = load_obj(file);
  EXPECT_TRUE(well_formed(mesh));
  EXPECT_EQ(mesh.triangles.size(), 1u);
  EXPECT_EQ(warnings.text(), "airlight: warning: " + file.string() + ": skipped 1 degenerate triangle (zero area)\n");
}

// Triangles with a repeated corner (by index or by position) join nothing once welded:
// skipping them keeps a closed box closed.
TEST(ObjMesh, SkippingSliversKeepsAClosedMeshClosed) {
  const Mesh box = make_box(glm::vec3(0.0f), glm::vec3(1.0f, 2.0f, 3.0f));
  ASSERT_TRUE(solid::closed(box.positions, box.triangles));
  const size_t n = box.positions.size();
  const glm::vec3 p = box.positions[0];
  const std::string slivers = "v " + std::to_string(p.x) + " " + std::to_string(p.y) + " " + std::to_string(p.z) +
                              "\nf 1 " + std::to_string(n + 1) + " 2\nf 3 3 4\n";
  const auto file = write_obj("box_slivers.obj", obj_text(box) + slivers);
  const Warnings warnings;
  const Mesh mesh = load_obj(file);
  EXPECT_TRUE(well_formed(mesh));
  EXPECT_EQ(mesh.triangles.size(), box.triangles.size());
  EXPECT_TRUE(solid::closed(mesh.positions, mesh.triangles));
  EXPECT_EQ(warnings.text(), "airlight: warning: " + file.string() + ": skipped 2 degenerate triangles (zero area)\n");
}

// A tetrahedron whose bottom face is split at the middle of edge 1-2 (vertex 5) while the
// side face 1 2 4 is not: face 6, three distinct corners in a line, closes the T-junction.
TEST(ObjMesh, ADegenerateTriangleThatClosesTheSurfaceIsAnError) {
  const auto file = write_obj("t_junction.obj",
                              "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nv 0.5 0 0\n"
                              "f 1 2 4\nf 2 3 4\nf 3 1 4\nf 2 5 3\nf 5 1 3\nf 1 5 2\n");
  EXPECT_TRUE(throws_input_error([&] { load_obj(file); }, file.string(), "face 6",
                                 "has zero area (its corners lie on a line) but closes the surface, which skipping "
                                 "it would open; split the face across its longest edge at its middle corner instead"));
}

TEST(ObjMesh, OnlyDegenerateTrianglesIsNoFaces) {
  const auto file = write_obj("flat.obj", "v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\nf 1 1 2\n");
  EXPECT_TRUE(throws_input_error([&] { load_obj(file); }, file.string(), "", "has no faces"));
}

// A vertex line tinyobjloader would misread (as 0 or as infinity) and what the error says.
struct BadVertex {
  const char* name;
  const char* line;
  const char* message;
};

void PrintTo(const BadVertex& c, std::ostream* out) { *out << c.name; }

class BadObjVertex : public ::testing::TestWithParam<BadVertex> {};

TEST_P(BadObjVertex, NamesTheVertexAndWhatIsWrong) {
  const BadVertex& c = GetParam();
  const auto file = write_obj(std::string(c.name) + ".obj", "v 0 0 0\nv 1 0 0\n" + std::string(c.line) + "\nf 1 2 3\n");
  EXPECT_TRUE(throws_input_error([&] { load_obj(file); }, file.string(), "vertex 3", c.message));
}

const BadVertex kBadVertices[] = {
    {"Nan", "v nan 0 0", "has a non-finite coordinate (nan)"},
    {"Infinity", "v 0 -inf 1", "has a non-finite coordinate (-inf)"},
    {"Word", "v 0 1 abc", "has a coordinate that is not a number ('abc')"},
    {"BeyondDouble", "v 1e999 0 1", "has a coordinate beyond float range (larger than 3.40282e+38)"},
    {"BeyondFloat", "v 0 1e39 1", "has a coordinate beyond float range (larger than 3.40282e+38)"},
    {"TooFar", "v 0 1e31 1", "is too far from the origin (more than 1e+30)"},
    {"TwoCoordinates", "v 0 1", "has fewer than 3 coordinates"},
};

INSTANTIATE_TEST_SUITE_P(ObjMesh, BadObjVertex, ::testing::ValuesIn(kBadVertices),
                         [](const ::testing::TestParamInfo<BadVertex>& info) { return std::string(info.param.name); });

TEST(ObjMesh, MissingVertexNamesTheFileAndFace) {
  const auto file = data_dir() / "bad_index.obj";
  EXPECT_TRUE(throws_input_error([&] { load_obj(file); }, file.string(), "face 1", "refers to a missing vertex"));
}

// OBJ's relative indices: -1 is the last vertex written so far.
TEST(ObjMesh, NegativeIndicesCountBackFromTheLastVertex) {
  const auto file = write_obj("relative.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nf -3 -2 -1\nv 0 1 0\nf 1 3 -1\n");
  const Mesh mesh = load_obj(file);
  ASSERT_TRUE(well_formed(mesh));
  ASSERT_EQ(mesh.triangles.size(), 2u);
  const auto corner = [&](size_t t, int k) { return mesh.positions[mesh.triangles[t][k]]; };
  EXPECT_EQ(corner(0, 2), glm::vec3(1, 1, 0));
  EXPECT_EQ(corner(1, 2), glm::vec3(0, 1, 0));
}

// Lines and points have no area: left out, counted in one warning; the faces load.
TEST(ObjMesh, LinesAndPointsAreSkippedWithAWarningThatCountsThem) {
  const auto file = write_obj("lines.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nl 1 2\nl 2 3 1\np 1\nf 1 2 3\n");
  const Warnings warnings;
  const Mesh mesh = load_obj(file);
  EXPECT_EQ(mesh.triangles.size(), 1u);
  EXPECT_EQ(warnings.text(), "airlight: warning: " + file.string() +
                                 ": skipped 2 lines and 1 point (airlight renders faces)\n");
  const auto only = write_obj("only_lines.obj", "v 0 0 0\nv 1 0 0\nl 1 2\n");
  EXPECT_TRUE(throws_input_error([&] { load_obj(only); }, only.string(), "", "has no faces"));
}

// Materials play no part: a usemtl whose .mtl is missing loads, saying so once.
TEST(ObjMesh, UsemtlWithoutItsMaterialFileIsIgnoredWithAWarning) {
  const std::string faces = "v 0 0 0\nv 1 0 0\nv 1 1 0\nusemtl red\nf 1 2 3\nusemtl blue\nf 1 3 2\n";
  const auto missing = write_obj("materials.obj", "mtllib missing.mtl\n" + faces);
  const Warnings warnings;
  EXPECT_EQ(load_obj(missing).triangles.size(), 2u);
  const auto no_library = write_obj("no_mtllib.obj", faces);
  EXPECT_EQ(load_obj(no_library).triangles.size(), 2u);
  EXPECT_EQ(warnings.text(),
            "airlight: warning: " + missing.string() +
                ": usemtl without its material file (missing.mtl is not there): materials are ignored, the "
                "object's albedo applies\n"
                "airlight: warning: " + no_library.string() +
                ": usemtl without its material file (no mtllib line): materials are ignored, the object's "
                "albedo applies\n");
}

TEST(ObjMesh, UnreadableFileNamesTheFile) {
  const auto file = data_dir() / "no_such.obj";
  EXPECT_TRUE(throws_input_error([&] { load_obj(file); }, file.string(), ""));
}

}  // namespace
}  // namespace airlight
