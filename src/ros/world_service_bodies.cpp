// SetBodyState: one body's pose and twist, and the kinematic hold of a drag.
#include "collision2d/ros/world_service.h"

#include <stdexcept>
#include <string>

#include <ros/console.h>

#include "collision2d/ros/conversions.h"
#include "collision2d/ros/validation.h"
#include "service_reply.h"

namespace collision2d
{
namespace ros_interface
{
namespace
{
const char* type_name(BodyType type)
{
  switch (type)
  {
    case BodyType::Dynamic:
      return "DYNAMIC";
    case BodyType::Static:
      return "STATIC";
    case BodyType::Kinematic:
      return "KINEMATIC";
  }
  return "?";
}

}  // namespace

void WorldService::set_body_state(const SetBodyState::Request& request, SetBodyState::Response& response)
{
  serve(response, "set_body_state", [&] {
    const std::string where = "id " + std::to_string(request.id);
    check_pose_and_twist(request.pose, request.twist, where);
    Lock lock(mutex_);
    if (!world_.has_body(request.id))
    {
      reject(where, "no body with this id in the world");
    }
    const Vec2 centre{request.pose.x, request.pose.y};
    for (BodyId other : world_.body_ids())
    {
      if (other != request.id && world_.body(other).position() == centre)
      {
        reject(where, "pose: centre coincides with that of body id " + std::to_string(other) +
                          "; overlapping bodies with one centre have no contact normal");
      }
    }
    // Everything is built on copies, installed only when all of it worked.
    World next = world_;
    std::map<BodyId, BodyType> held = held_;
    const auto was_held = held.find(request.id);
    const bool held_before = was_held != held.end();
    const BodyType type = world_.body(request.id).type();
    if (request.hold && was_held == held.end() && type != BodyType::Kinematic)
    {
      held[request.id] = type;
      next.set_body_type(request.id, BodyType::Kinematic);
    }
    else if (!request.hold && was_held != held.end())
    {
      next.set_body_type(request.id, was_held->second);
      held.erase(was_held);
    }
    try
    {
      next.set_body_state(request.id, centre, request.pose.theta,
                          Vec2{request.twist.linear.x, request.twist.linear.y}, request.twist.angular.z);
    }
    catch (const std::invalid_argument& e)
    {
      reject(where, e.what());
    }
    held_ = std::move(held);
    commit(std::move(next), scene_, Change::Edit);
    response.success = true;
    const BodyType now = world_.body(request.id).type();
    response.message = "body id " + std::to_string(request.id) + " set" +
                       (request.hold ? " and held as KINEMATIC" : std::string(" (") + type_name(now) + ")");
    if (request.hold != held_before)
    {
      ROS_INFO_NAMED(kWorldLogger, "%s", response.message.c_str());  // a hold begins or ends
    }
    else
    {
      ROS_DEBUG_NAMED(kWorldLogger, "%s", response.message.c_str());
    }
  });
}

}  // namespace ros_interface
}  // namespace collision2d
