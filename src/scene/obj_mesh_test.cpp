#include "scene/shapes.hpp"
#include "scene/test_support.hpp"

#include <gtest/gtest.h>

namespace airlight {
namespace {

using namespace scene_mesh;
using scene_test::data_dir;
using scene_test::misoriented_fraction;
using scene_test::signed_volume;
using scene_test::throws_input_error;
using scene_test::well_formed;

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

TEST(ObjMesh, DegenerateTriangleNamesTheFileAndFace) {
  const auto file = data_dir() / "degenerate.obj";
  EXPECT_TRUE(throws_input_error([&] { load_obj(file); }, file.string(), "face 2"));
}

TEST(ObjMesh, MissingVertexNamesTheFileAndFace) {
  const auto file = data_dir() / "bad_index.obj";
  EXPECT_TRUE(throws_input_error([&] { load_obj(file); }, file.string(), "face 1"));
}

TEST(ObjMesh, UnreadableFileNamesTheFile) {
  const auto file = data_dir() / "no_such.obj";
  EXPECT_TRUE(throws_input_error([&] { load_obj(file); }, file.string(), ""));
}

}  // namespace
}  // namespace airlight
