// Helpers shared by the scene tests: field-by-field comparison of scenes,
// bodies, materials and settings, so a builder or round trip that changes
// any of them fails naming it.
#pragma once

#include <gtest/gtest.h>

#include <string>

#include "collision2d/body.h"
#include "collision2d/scene.h"
#include "settings_test_support.h"

namespace collision2d
{
namespace test
{
inline void expect_same_material(const Material& a, const Material& b, const std::string& where)
{
  EXPECT_EQ(a.restitution, b.restitution) << where;
  EXPECT_EQ(a.static_friction, b.static_friction) << where;
  EXPECT_EQ(a.kinetic_friction, b.kinetic_friction) << where;
}

/// Bit-for-bit equality of everything a body carries (vertices within
/// `vertex_tolerance`, see scene_yaml_write.cpp on recentring).
inline void expect_same_body(const SceneBody& a, const SceneBody& b, const std::string& where,
                             double vertex_tolerance = 0.0)
{
  EXPECT_EQ(a.name, b.name) << where;
  EXPECT_EQ(a.body.shape(), b.body.shape()) << where;
  EXPECT_EQ(a.body.type(), b.body.type()) << where;
  EXPECT_EQ(a.body.mass(), b.body.mass()) << where;
  EXPECT_EQ(a.body.position(), b.body.position()) << where;
  EXPECT_EQ(a.body.velocity(), b.body.velocity()) << where;
  EXPECT_EQ(a.body.theta(), b.body.theta()) << where;
  EXPECT_EQ(a.body.omega(), b.body.omega()) << where;
  ASSERT_EQ(a.body.vertex_count(), b.body.vertex_count()) << where;
  if (vertex_tolerance == 0.0)
  {
    EXPECT_EQ(a.body.radius(), b.body.radius()) << where;
    EXPECT_EQ(a.body.inertia(), b.body.inertia()) << where;
  }
  for (std::size_t i = 0; i < a.body.vertex_count(); ++i)
  {
    EXPECT_NEAR(a.body.local_vertices()[i].x, b.body.local_vertices()[i].x, vertex_tolerance) << where;
    EXPECT_NEAR(a.body.local_vertices()[i].y, b.body.local_vertices()[i].y, vertex_tolerance) << where;
  }
  expect_same_material(a.material, b.material, where);
}

inline void expect_same_settings(const WorldSettings& a, const WorldSettings& b)
{
  test::expect_same_world_settings(a, b);
}

inline void expect_same_scene(const Scene& a, const Scene& b, double vertex_tolerance = 0.0)
{
  EXPECT_EQ(a.name, b.name);
  expect_same_settings(a.settings, b.settings);
  ASSERT_EQ(a.bodies.size(), b.bodies.size()) << a.name;
  for (std::size_t i = 0; i < a.bodies.size(); ++i)
  {
    expect_same_body(a.bodies[i], b.bodies[i], a.name + " body " + std::to_string(i), vertex_tolerance);
  }
}

}  // namespace test
}  // namespace collision2d
