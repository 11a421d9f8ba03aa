// make_indenter: the case-file spec gives the right shape; bad specs are input errors naming
// indenter.<key>.
#include "contact/indenter_factory.hpp"

#include <gtest/gtest.h>

#include "core/error.hpp"

namespace si {
namespace {

IndenterSpec spec_of(IndenterShape shape) {
  IndenterSpec spec;
  spec.shape = shape;
  spec.radius = 5.0;
  spec.edge_radius = 1.0;
  spec.length = 10.0;
  spec.a = spec.b = spec.c = 5.0;
  return spec;
}

void expect_input_error(const IndenterSpec& spec, const IndenterPose& pose,
                        const std::string& key) {
  try {
    make_indenter(spec, pose);
    ADD_FAILURE() << "expected an input error naming " << key;
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::kInput);
    EXPECT_EQ(e.where().key, key);
    EXPECT_NE(std::string(e.what()).find(key), std::string::npos) << e.what();
  }
}

TEST(IndenterFactory, BuildsEachShape) {
  const IndenterPose pose;
  EXPECT_EQ(make_indenter(spec_of(IndenterShape::kSphere), pose)->name(), "sphere");
  EXPECT_EQ(make_indenter(spec_of(IndenterShape::kSuperquadric), pose)->name(), "superquadric");
  EXPECT_EQ(make_indenter(spec_of(IndenterShape::kFlatPunch), pose)->name(), "flat_punch");
  EXPECT_EQ(make_indenter(spec_of(IndenterShape::kCylinder), pose)->name(), "cylinder");
}

TEST(IndenterFactory, NormalisesTheDirection) {
  IndenterPose pose;
  pose.direction = Vector3d(0, 0, -4);
  const auto sphere = make_indenter(spec_of(IndenterShape::kSphere), pose);
  EXPECT_NEAR(sphere->signed_distance(Vector3d(0, 0, -10), 2.0, nullptr, nullptr), 3.0, 1e-12);
}

TEST(IndenterFactory, RejectsBadSpecs) {
  const IndenterPose pose;
  IndenterSpec s = spec_of(IndenterShape::kSphere);
  s.radius = 0.0;
  expect_input_error(s, pose, "indenter.radius");

  s = spec_of(IndenterShape::kFlatPunch);
  s.edge_radius = 5.0;  // = radius
  expect_input_error(s, pose, "indenter.edge_radius");
  s.edge_radius = -0.1;
  expect_input_error(s, pose, "indenter.edge_radius");

  s = spec_of(IndenterShape::kSuperquadric);
  s.b = -1.0;
  expect_input_error(s, pose, "indenter.b");
  s = spec_of(IndenterShape::kSuperquadric);
  s.e1 = 2.5;
  expect_input_error(s, pose, "indenter.e1");

  s = spec_of(IndenterShape::kCylinder);
  s.length = -1.0;
  expect_input_error(s, pose, "indenter.length");
  IndenterPose parallel;
  parallel.axis = Vector3d(0, 0, 1);
  expect_input_error(spec_of(IndenterShape::kCylinder), parallel, "indenter.axis");

  IndenterPose still;
  still.direction = Vector3d::Zero();
  expect_input_error(spec_of(IndenterShape::kSphere), still, "indenter.direction");
}

}  // namespace
}  // namespace si
