// The world frame models enter (engine/model/model_frame.hpp): a y-up file's (x, y, z) becomes
// (x, -z, y), as Blender's importers put it. glTF is y-up by its specification; an OBJ's up axis is the
// scene's to say, y by default.
#include <gtest/gtest.h>

#include "engine/core/error.hpp"
#include "engine/model/model_loader.hpp"
#include "engine/render/placed_model.hpp"
#include "support/test_data.hpp"

namespace lp::render {
namespace {

// tests/data/models/obj/quad.obj: the unit square in z = 0, facing +z.
MeshObject obj_quad(std::optional<UpAxis> up) {
  MeshObject m;
  m.path = test::model_path("obj/quad.obj");
  m.up_axis = up;
  return m;
}

TEST(ModelFrame, AYUpFileTurnsItsUpToZAndItsFrontToMinusY) {
  const Mat4 r = y_up_to_world();
  EXPECT_EQ(r.point({1, 2, 3}), (Vec3{1, -3, 2}));
  EXPECT_EQ(r.vector({0, 1, 0}), (Vec3{0, 0, 1}));   // up
  EXPECT_EQ(r.vector({0, 0, 1}), (Vec3{0, -1, 0}));  // front, towards a camera on -y
  EXPECT_DOUBLE_EQ(r.determinant3(), 1.0);           // a rotation: handedness and winding kept
}

TEST(ModelFrame, AnObjIsYUpUnlessTheSceneSaysZ) {
  const Model y = place_model(obj_quad(std::nullopt), {});
  const Model y_given = place_model(obj_quad(UpAxis::Y), {});
  const Model z = place_model(obj_quad(UpAxis::Z), {});
  const Model file = load_model(test::model_path("obj/quad.obj"), {});
  ASSERT_EQ(file.vertex_count(), z.vertex_count());
  for (size_t i = 0; i < file.vertex_count(); ++i) {
    const Vec3 p = file.positions[i];
    EXPECT_EQ(z.positions[i], p);
    EXPECT_EQ(y.positions[i], (Vec3{p.x, -p.z, p.y}));
    EXPECT_EQ(y_given.positions[i], y.positions[i]);
    EXPECT_NEAR(dot(y.normals[i], file.normals[i]), 0.0f, 1e-6f);
    EXPECT_NEAR(y.normals[i].z, file.normals[i].y, 1e-6f);
  }
}

TEST(ModelFrame, AGltfIsYUpByItsSpecificationAndRefusesZ) {
  MeshObject gltf;
  gltf.path = test::model_path("quad.glb");
  const Model m = place_model(gltf, {});
  EXPECT_EQ(m.normals[0], (Vec3{0, -1, 0}));  // its front (+z) faces -y
  gltf.up_axis = UpAxis::Y;
  EXPECT_EQ(place_model(gltf, {}).positions, m.positions);
  gltf.up_axis = UpAxis::Z;
  try {
    place_model(gltf, {});
    ADD_FAILURE() << "a glTF placed z-up";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::InvalidArgument);
    EXPECT_STREQ(e.what(), "a glTF model is y-up by its specification; z applies to OBJ files");
  }
}

}  // namespace
}  // namespace lp::render
