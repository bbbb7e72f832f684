// The node's sim clock, printable messages and SetBodyState's kinematic hold:
// no master needed.
#include <cmath>
#include <limits>
#include <string>

#include <gtest/gtest.h>
#include <ros/time.h>

#include "collision2d/ros/printable.h"
#include "collision2d/ros/validation.h"
#include "collision2d/ros/world_outputs.h"
#include "collision2d/ros/world_service.h"

namespace collision2d
{
namespace ros_interface
{
namespace
{
TEST(SimClock, FollowsTheWorldAndNeverRunsBackwards)
{
  SimClock clock;
  EXPECT_EQ(clock.stamp(0.0).toNSec(), 0u);
  EXPECT_EQ(clock.stamp(0.5).toNSec(), 500000000u);
  // A change that does not advance the world still gets a later stamp.
  EXPECT_EQ(clock.stamp(0.5).toNSec(), 500001000u);
  // A reset: the world starts again at 0, the clock goes on.
  const ros::Time after_reset = clock.stamp(0.0);
  EXPECT_EQ(after_reset.toNSec(), 500002000u);
  EXPECT_EQ(clock.stamp(0.25).toNSec(), 750002000u);
  // A restored snapshot far ahead: the clock moves on with it, keeping its offset.
  EXPECT_EQ(clock.stamp(10.0).toNSec(), 10500002000u);
}

TEST(PrintableText, EscapesRawBytesAndKeepsText)
{
  EXPECT_EQ(printable_text("plain: 1 m/s\n\tnext"), "plain: 1 m/s\n\tnext");
  EXPECT_EQ(printable_text("Gr\xC3\xBC\xC3\x9F" "e \xE2\x80\x93 \xF0\x9F\x98\x80"), "Gr\xC3\xBC\xC3\x9F" "e \xE2\x80\x93 \xF0\x9F\x98\x80");
  EXPECT_EQ(printable_text("\xFF\xFE" "a\x01\x1B[31m"), "\\xFF\\xFE" "a\\x01\\x1B[31m");
  // Truncated, overlong and surrogate sequences are not UTF-8.
  EXPECT_EQ(printable_text("\xC3"), "\\xC3");
  EXPECT_EQ(printable_text("\xC0\xAF"), "\\xC0\\xAF");
  EXPECT_EQ(printable_text("\xED\xA0\x80"), "\\xED\\xA0\\x80");
  EXPECT_EQ(printable_text(std::string("a\0b", 3)), "a\\x00b");
  EXPECT_EQ(printable_text("mass = -nan is not finite"), "mass = nan is not finite");
}

TEST(PrintableText, NanIsWrittenWithoutSign)
{
  EXPECT_EQ(format_number(-std::numeric_limits<double>::quiet_NaN()), "nan");
  EXPECT_EQ(format_number(std::numeric_limits<double>::quiet_NaN()), "nan");
}

class SetBodyStateTest : public ::testing::Test
{
protected:
  static void SetUpTestCase() { ::ros::Time::init(); }

  void SetUp() override
  {
    service_.load("bouncing_disks");
    StepWorld::Request step;
    step.frames = 3;
    StepWorld::Response stepped;
    service_.step(step, stepped);
    ASSERT_TRUE(stepped.success) << stepped.message;
    before_ = service_.state();
    id_ = before_.bodies.back().id;
  }

  SetBodyState::Response set(double x, double vx, bool hold)
  {
    SetBodyState::Request request;
    request.id = id_;
    request.pose.x = x;
    request.pose.y = 20.0;
    request.twist.linear.x = vx;
    request.hold = hold;
    SetBodyState::Response response;
    service_.set_body_state(request, response);
    return response;
  }

  const BodyMsg& body() const
  {
    state_ = service_.state();
    for (const BodyMsg& b : state_.bodies)
    {
      if (b.id == id_)
      {
        return b;
      }
    }
    throw std::runtime_error("body gone");
  }

  WorldService service_{WorldServiceOptions{}};
  WorldState before_;
  mutable WorldState state_;
  std::uint32_t id_ = 0;
};

TEST_F(SetBodyStateTest, HoldIsKinematicAndReleaseRestoresTheTypeWithTheVelocity)
{
  ASSERT_EQ(body().type, BodyMsg::DYNAMIC);
  ASSERT_TRUE(set(1.0, 0.0, true).success);
  EXPECT_EQ(body().type, BodyMsg::KINEMATIC);
  ASSERT_TRUE(set(1.5, 2.0, true).success);
  EXPECT_EQ(body().pose.x, 1.5);
  EXPECT_EQ(body().type, BodyMsg::KINEMATIC);
  const SetBodyState::Response released = set(1.6, 2.5, false);
  ASSERT_TRUE(released.success) << released.message;
  EXPECT_EQ(body().type, BodyMsg::DYNAMIC);
  EXPECT_EQ(body().pose.x, 1.6);
  EXPECT_EQ(body().twist.linear.x, 2.5);
  // Rebuilding the world for the hold keeps its clock, ids and bodies.
  const WorldState after = service_.state();
  EXPECT_EQ(after.frame_count, before_.frame_count);
  EXPECT_EQ(after.sim_time, before_.sim_time);
  ASSERT_EQ(after.bodies.size(), before_.bodies.size());
  for (std::size_t i = 0; i < after.bodies.size(); ++i)
  {
    EXPECT_EQ(after.bodies[i].id, before_.bodies[i].id);
  }
}

TEST_F(SetBodyStateTest, RefusedRequestsNameBodyAndFieldAndChangeNothing)
{
  ASSERT_TRUE(set(1.0, 0.0, true).success);
  const WorldState held = service_.state();
  const SetBodyState::Response bad = set(std::numeric_limits<double>::quiet_NaN(), 0.0, false);
  EXPECT_FALSE(bad.success);
  EXPECT_EQ(bad.message, "id " + std::to_string(id_) + ": pose.x = nan is not finite");
  EXPECT_EQ(body().type, BodyMsg::KINEMATIC);  // still held
  SetBodyState::Request unknown;
  unknown.id = 100000;
  SetBodyState::Response response;
  service_.set_body_state(unknown, response);
  EXPECT_FALSE(response.success);
  EXPECT_NE(response.message.find("id 100000"), std::string::npos) << response.message;
  SetBodyState::Request onto;
  onto.id = id_;
  onto.pose.x = before_.bodies.front().pose.x;
  onto.pose.y = before_.bodies.front().pose.y;
  service_.set_body_state(onto, response);
  EXPECT_FALSE(response.success);
  EXPECT_NE(response.message.find("centre coincides"), std::string::npos) << response.message;
  WorldState now = service_.state();
  now.header = held.header;
  EXPECT_TRUE(now == held);
}

}  // namespace
}  // namespace ros_interface
}  // namespace collision2d
