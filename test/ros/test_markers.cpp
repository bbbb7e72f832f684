// The WorldState -> rviz markers conversion and its DELETE bookkeeping, without
// a master. Geometry is checked in the world frame against outlines computed
// here from the bodies' poses, so a wrong pose, rotation or triangulation fails.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include <gtest/gtest.h>

#include "collision2d/ros/messages.h"

#include "collision2d/ros/marker_colors.h"
#include "collision2d/ros/markers.h"
#include "marker_model.h"

namespace collision2d
{
namespace ros_interface
{
namespace
{
using BodyMsgT = WorldState::_bodies_type::value_type;
using ContactMsgT = WorldState::_contacts_type::value_type;
using test::MarkerModel;
using test::Point2;
using visualization_msgs::Marker;
using visualization_msgs::MarkerArray;

constexpr double kTol = 1e-9;
constexpr double kPi = 3.14159265358979323846;
// A pentagon (counter-clockwise, body frame, centroid not at the origin on
// purpose: the markers must use the vertices as given).
const std::vector<Point2> kPentagon = {{1.0, 0.0}, {0.4, 0.9}, {-0.8, 0.6}, {-0.8, -0.6}, {0.3, -0.95}};

BodyMsgT disk(std::uint32_t id, double x, double y, double radius, double theta = 0.0)
{
  BodyMsgT body;
  body.id = id;
  body.shape = BodyMsgT::DISK;
  body.type = BodyMsgT::DYNAMIC;
  body.mass = 1.0;
  body.radius = radius;
  body.pose.x = x;
  body.pose.y = y;
  body.pose.theta = theta;
  return body;
}

BodyMsgT polygon(std::uint32_t id, const std::vector<Point2>& outline, double x, double y, double theta)
{
  BodyMsgT body = disk(id, x, y, 1.0, theta);
  body.shape = BodyMsgT::POLYGON;
  for (const Point2& p : outline)
  {
    body.vertices.emplace_back();
    body.vertices.back().x = p.x;
    body.vertices.back().y = p.y;
  }
  return body;
}

WorldState state_of(const std::vector<BodyMsgT>& bodies, std::uint64_t frame = 1, const char* scene = "test")
{
  WorldState state;
  state.header.frame_id = "world_frame";
  state.frame_count = frame;
  state.scene = scene;
  state.bodies = bodies;
  return state;
}

std::vector<const Marker*> in_namespace(const MarkerArray& array, const char* ns)
{
  std::vector<const Marker*> out;
  for (const auto& marker : array.markers)
  {
    if (marker.ns == ns)
    {
      out.push_back(&marker);
    }
  }
  return out;
}

const Marker& only(const MarkerArray& array, const char* ns)
{
  const auto markers = in_namespace(array, ns);
  EXPECT_EQ(markers.size(), 1U) << ns;
  return *markers.at(0);
}

double signed_area(Point2 a, Point2 b, Point2 c)
{
  return 0.5 * ((b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y));
}

double shoelace_area(const std::vector<Point2>& outline)
{
  double twice = 0.0;
  for (std::size_t i = 0; i < outline.size(); ++i)
  {
    const Point2& a = outline[i];
    const Point2& b = outline[(i + 1) % outline.size()];
    twice += a.x * b.y - b.x * a.y;
  }
  return 0.5 * twice;
}

void expect_near(Point2 actual, Point2 expected, const char* what)
{
  EXPECT_NEAR(actual.x, expected.x, kTol) << what;
  EXPECT_NEAR(actual.y, expected.y, kTol) << what;
}

bool is_grey(const std_msgs::ColorRGBA& c)
{
  return c.r == c.g && c.g == c.b;
}

double color_distance(const std_msgs::ColorRGBA& a, const std_msgs::ColorRGBA& b)
{
  return std::sqrt((a.r - b.r) * (a.r - b.r) + (a.g - b.g) * (a.g - b.g) + (a.b - b.b) * (a.b - b.b));
}

TEST(WorldStateMarkers, DiskIsAFlatCylinderWithATurningRadius)
{
  const double x = 1.5, y = -2.0, r = 0.7, theta = 2.0;
  const MarkerArray array = world_state_markers(state_of({disk(4, x, y, r, theta)}), MarkerOptions());

  const Marker& fill = only(array, marker_ns::kBodies);
  EXPECT_EQ(fill.type, Marker::CYLINDER);
  EXPECT_EQ(fill.id, 4);
  EXPECT_EQ(fill.action, Marker::ADD);
  EXPECT_NEAR(fill.pose.position.x, x, kTol);
  EXPECT_NEAR(fill.pose.position.y, y, kTol);
  EXPECT_NEAR(fill.scale.x, 2.0 * r, kTol);
  EXPECT_NEAR(fill.scale.y, 2.0 * r, kTol);
  EXPECT_GT(fill.scale.z, 0.0);
  EXPECT_LT(fill.scale.z, r) << "flat";

  const Marker& radius = only(array, marker_ns::kRotation);
  EXPECT_EQ(radius.type, Marker::LINE_LIST);
  EXPECT_EQ(radius.id, 4);
  ASSERT_EQ(radius.points.size(), 2U);
  expect_near(test::to_world(radius, radius.points[0]), {x, y}, "radius starts at the centre");
  expect_near(test::to_world(radius, radius.points[1]), {x + r * std::cos(theta), y + r * std::sin(theta)},
              "radius ends on the rim at theta");
  EXPECT_TRUE(in_namespace(array, marker_ns::kOutlines).empty()) << "disks have no polygon outline";
}

TEST(WorldStateMarkers, PolygonIsFilledByTrianglesCoveringItsOutline)
{
  const double x = -3.0, y = 4.0, theta = 0.6;
  const MarkerArray array = world_state_markers(state_of({polygon(9, kPentagon, x, y, theta)}), MarkerOptions());
  std::vector<Point2> world;
  for (const Point2& p : kPentagon)
  {
    world.push_back(test::place(p, x, y, theta));
  }

  const Marker& fill = only(array, marker_ns::kBodies);
  EXPECT_EQ(fill.type, Marker::TRIANGLE_LIST);
  EXPECT_EQ(fill.id, 9);
  ASSERT_EQ(fill.points.size(), 3 * (kPentagon.size() - 2));
  double covered = 0.0;
  for (std::size_t t = 0; t < fill.points.size(); t += 3)
  {
    const Point2 a = test::to_world(fill, fill.points[t]);
    const Point2 b = test::to_world(fill, fill.points[t + 1]);
    const Point2 c = test::to_world(fill, fill.points[t + 2]);
    EXPECT_GT(signed_area(a, b, c), 0.0) << "triangle " << t / 3 << " faces the viewer (counter-clockwise)";
    covered += signed_area(a, b, c);
    for (const Point2& corner : {a, b, c})
    {
      const bool on_outline = std::any_of(world.begin(), world.end(), [&](const Point2& v) {
        return std::hypot(v.x - corner.x, v.y - corner.y) < kTol;
      });
      EXPECT_TRUE(on_outline) << "triangle corners are polygon vertices";
    }
  }
  EXPECT_NEAR(covered, shoelace_area(world), kTol) << "the triangles tile the polygon exactly";

  const Marker& outline = only(array, marker_ns::kOutlines);
  EXPECT_EQ(outline.type, Marker::LINE_STRIP);
  EXPECT_EQ(outline.id, 9);
  ASSERT_EQ(outline.points.size(), kPentagon.size() + 1) << "closed loop";
  for (std::size_t i = 0; i <= kPentagon.size(); ++i)
  {
    expect_near(test::to_world(outline, outline.points[i]), world[i % world.size()], "outline vertex");
  }
  EXPECT_TRUE(in_namespace(array, marker_ns::kRotation).empty()) << "the outline already shows a polygon's angle";
}

TEST(WorldStateMarkers, IdsFollowBodyIdsNotArrayOrder)
{
  const WorldState state = state_of({disk(7, 0, 0, 1), polygon(3, kPentagon, 5, 0, 0), disk(12, 9, 0, 1)});
  const MarkerArray array = world_state_markers(state, MarkerOptions());
  std::vector<int> ids;
  for (const Marker* m : in_namespace(array, marker_ns::kBodies))
  {
    ids.push_back(m->id);
    EXPECT_NEAR(m->pose.position.x, m->id == 7 ? 0.0 : m->id == 3 ? 5.0 : 9.0, kTol) << "id " << m->id;
  }
  std::sort(ids.begin(), ids.end());
  EXPECT_EQ(ids, (std::vector<int>{3, 7, 12}));
}

TEST(WorldStateMarkers, FrameIdComesFromTheOptionsOrTheState)
{
  const WorldState state = state_of({disk(0, 0, 0, 1)});
  MarkerOptions options;
  for (const auto& m : world_state_markers(state, options).markers)
  {
    EXPECT_EQ(m.header.frame_id, "world_frame");
  }
  options.frame_id = "map";
  for (const auto& m : world_state_markers(state, options).markers)
  {
    EXPECT_EQ(m.header.frame_id, "map");
  }
}

TEST(WorldStateMarkers, ColoursTellBodyTypesApartAndDynamicBodiesApart)
{
  WorldState state;
  for (std::uint32_t id = 0; id < 12; ++id)
  {
    state.bodies.push_back(disk(id, 2.0 * id, 0, 0.5));
  }
  state.bodies[0].type = BodyMsgT::STATIC;
  state.bodies[1].type = BodyMsgT::KINEMATIC;
  const MarkerArray array = world_state_markers(state, MarkerOptions());
  const auto fills = in_namespace(array, marker_ns::kBodies);
  ASSERT_EQ(fills.size(), 12U);

  EXPECT_TRUE(is_grey(fills[0]->color)) << "static bodies are grey";
  EXPECT_FALSE(is_grey(fills[1]->color)) << "kinematic bodies are coloured";
  constexpr double kDistinct = 0.1;  // RGB distance that reads as another colour
  for (std::size_t i = 2; i < fills.size(); ++i)
  {
    const auto& c = fills[i]->color;
    EXPECT_EQ(c.a, 1.0F);
    EXPECT_GT(std::max({c.r, c.g, c.b}) - std::min({c.r, c.g, c.b}), 0.5F) << "dynamic body " << i << " is saturated";
    EXPECT_GT(color_distance(c, fills[1]->color), kDistinct) << "dynamic body " << i << " vs kinematic";
    EXPECT_GT(color_distance(c, fills[i - 1]->color), kDistinct) << "neighbour ids " << i - 1 << ", " << i;
  }
}

TEST(WorldStateMarkers, ContactArrowsStartAtThePointAlongTheNormalScaledByImpulse)
{
  WorldState state = state_of({disk(0, 0, 0, 1), disk(1, 2, 0, 1)});
  const double nx = std::cos(0.3), ny = std::sin(0.3);
  for (double impulse : {4.0, 0.0})
  {
    ContactMsgT contact;
    contact.body_a = 0;
    contact.body_b = 1;
    contact.point.x = 1.0;
    contact.point.y = 0.2;
    contact.normal.x = nx;
    contact.normal.y = ny;
    contact.normal_impulse = impulse;
    state.contacts.push_back(contact);
  }
  MarkerOptions options;
  const MarkerArray array = world_state_markers(state, options);
  const auto arrows = in_namespace(array, marker_ns::kContacts);
  ASSERT_EQ(arrows.size(), 2U);
  const double lengths[] = {options.impulse_scale * 4.0, options.min_contact_arrow};
  for (std::size_t i = 0; i < 2; ++i)
  {
    const Marker& a = *arrows[i];
    EXPECT_EQ(a.type, Marker::ARROW);
    EXPECT_EQ(a.id, static_cast<int>(i));
    ASSERT_EQ(a.points.size(), 2U);
    EXPECT_NEAR(a.points[0].x, 1.0, kTol);
    EXPECT_NEAR(a.points[0].y, 0.2, kTol);
    EXPECT_NEAR(a.points[1].x - a.points[0].x, lengths[i] * nx, kTol);
    EXPECT_NEAR(a.points[1].y - a.points[0].y, lengths[i] * ny, kTol);
  }
  options.show_contacts = false;
  EXPECT_TRUE(in_namespace(world_state_markers(state, options), marker_ns::kContacts).empty());
}

TEST(WorldStateMarkers, VelocityArrowsAndLabelsOnlyWhenAsked)
{
  WorldState state = state_of({disk(0, 1, 2, 1), disk(1, 5, 2, 1), disk(2, 9, 2, 1)});
  state.bodies[0].twist.linear.x = 3.0;
  state.bodies[0].twist.linear.y = -4.0;
  state.bodies[2].type = BodyMsgT::STATIC;
  MarkerOptions options;
  EXPECT_TRUE(in_namespace(world_state_markers(state, options), marker_ns::kVelocities).empty());
  EXPECT_TRUE(in_namespace(world_state_markers(state, options), marker_ns::kLabels).empty());

  options.show_velocities = true;
  options.show_labels = true;
  const MarkerArray array = world_state_markers(state, options);
  const Marker& v = only(array, marker_ns::kVelocities);  // body 1 rests, body 2 is static
  EXPECT_EQ(v.type, Marker::ARROW);
  EXPECT_EQ(v.id, 0);
  ASSERT_EQ(v.points.size(), 2U);
  EXPECT_NEAR(v.points[0].x, 1.0, kTol);
  EXPECT_NEAR(v.points[0].y, 2.0, kTol);
  EXPECT_NEAR(v.points[1].x - v.points[0].x, options.velocity_scale * 3.0, kTol);
  EXPECT_NEAR(v.points[1].y - v.points[0].y, options.velocity_scale * -4.0, kTol);

  const auto labels = in_namespace(array, marker_ns::kLabels);
  ASSERT_EQ(labels.size(), 3U);
  for (const Marker* label : labels)
  {
    EXPECT_EQ(label->type, Marker::TEXT_VIEW_FACING);
    EXPECT_EQ(label->text, std::to_string(label->id));
    EXPECT_NEAR(label->pose.position.x, state.bodies[label->id].pose.x, kTol);
  }
}

TEST(MarkerBuilder, FirstArrayClearsEveryNamespaceBeforeDrawing)
{
  MarkerBuilder builder;
  const MarkerArray array = builder.build(state_of({disk(0, 0, 0, 1)}));
  ASSERT_FALSE(array.markers.empty());
  std::size_t deleteall = 0;
  while (deleteall < array.markers.size() && array.markers[deleteall].action == Marker::DELETEALL)
  {
    ++deleteall;
  }
  EXPECT_EQ(deleteall, 6U) << "one per namespace, all first";
  for (std::size_t i = deleteall; i < array.markers.size(); ++i)
  {
    EXPECT_EQ(array.markers[i].action, Marker::ADD);
  }
}

TEST(MarkerBuilder, RemovedBodiesAndEndedContactsAreDeleted)
{
  MarkerOptions options;
  options.show_labels = true;
  MarkerBuilder builder(options);
  MarkerModel rviz;
  WorldState state = state_of({disk(0, 0, 0, 1), polygon(1, kPentagon, 4, 0, 0), disk(2, 8, 0, 1)});
  state.contacts.resize(3);
  rviz.apply(builder.build(state));
  EXPECT_EQ(rviz.count(marker_ns::kBodies), 3U);
  EXPECT_EQ(rviz.count(marker_ns::kContacts), 3U);

  const MarkerArray unchanged = builder.build(state);
  for (const auto& m : unchanged.markers)
  {
    EXPECT_EQ(m.action, Marker::ADD) << "nothing to delete when nothing changed";
  }

  state.bodies.erase(state.bodies.begin() + 1);  // the polygon
  state.bodies.erase(state.bodies.begin());      // disk 0
  state.contacts.resize(1);
  state.frame_count = 2;
  rviz.apply(builder.build(state));
  EXPECT_EQ(rviz.count(marker_ns::kBodies), 1U);
  EXPECT_NE(rviz.find(marker_ns::kBodies, 2), nullptr);
  EXPECT_EQ(rviz.find(marker_ns::kOutlines, 1), nullptr);
  EXPECT_EQ(rviz.find(marker_ns::kRotation, 0), nullptr);
  EXPECT_EQ(rviz.find(marker_ns::kLabels, 0), nullptr);
  EXPECT_EQ(rviz.find(marker_ns::kLabels, 1), nullptr);
  EXPECT_EQ(rviz.count(marker_ns::kContacts), 1U);
  // Everything still shown is exactly what this state draws.
  EXPECT_EQ(rviz.size(), world_state_markers(state, options).markers.size());
}

TEST(MarkerBuilder, ResetOrNewSceneStartsWithDeleteAll)
{
  MarkerBuilder builder;
  WorldState state = state_of({disk(0, 0, 0, 1), disk(1, 3, 0, 1)}, 50, "demo");
  builder.build(state);
  const auto starts_with_deleteall = [](const MarkerArray& a) {
    return !a.markers.empty() && a.markers.front().action == Marker::DELETEALL;
  };

  state.frame_count = 60;
  EXPECT_FALSE(starts_with_deleteall(builder.build(state)));
  state.frame_count = 0;  // reset_world
  EXPECT_TRUE(starts_with_deleteall(builder.build(state)));
  state.frame_count = 5;
  state.scene = "pyramid";  // load_scene: frame count may not have gone back
  MarkerModel rviz;
  rviz.apply(builder.build(state));
  EXPECT_EQ(rviz.count(marker_ns::kBodies), 2U);
}

TEST(WorldStateMarkers, PoseOrientationIsTheBodyAngle)
{
  for (double theta : {0.0, 1.0, -2.5, kPi})
  {
    const MarkerArray array = world_state_markers(state_of({polygon(0, kPentagon, 0, 0, theta)}), MarkerOptions());
    EXPECT_NEAR(std::remainder(test::marker_yaw(only(array, marker_ns::kBodies)) - theta, 2.0 * kPi), 0.0, kTol);
  }
}

}  // namespace
}  // namespace ros_interface
}  // namespace collision2d
