// BodyMsg / ContactMsg <-> core Body / Contact.
#include "collision2d/ros/conversions.h"

#include <stdexcept>
#include <unordered_map>

namespace collision2d
{
namespace ros_interface
{
namespace
{
constexpr double kMaxRestitution = 1.0;

BodyType body_type_from_msg(std::uint8_t type, const std::string& where)
{
  switch (type)
  {
    case BodyMsg::DYNAMIC:
      return BodyType::Dynamic;
    case BodyMsg::STATIC:
      return BodyType::Static;
    case BodyMsg::KINEMATIC:
      return BodyType::Kinematic;
    default:
      reject(where, "type = " + std::to_string(type) + " is not DYNAMIC (0), STATIC (1) or KINEMATIC (2)");
  }
}

std::vector<Vec2> outline_from_msg(const BodyMsg& msg, const std::string& where)
{
  std::vector<Vec2> outline;
  outline.reserve(msg.vertices.size());
  for (std::size_t i = 0; i < msg.vertices.size(); ++i)
  {
    const std::string field = "vertices[" + std::to_string(i) + "]";
    require_finite(msg.vertices[i].x, where, field + ".x");
    require_finite(msg.vertices[i].y, where, field + ".y");
    outline.push_back({msg.vertices[i].x, msg.vertices[i].y});
  }
  check_polygon_outline(outline, where);
  return outline;
}

/// Fields are checked before the core sees them, so what reaches the core is
/// valid; anything the core still refuses is reported for this body too.
Body build_body(const BodyMsg& msg, const std::string& where)
{
  const Vec2 position{msg.pose.x, msg.pose.y};
  const Vec2 velocity{msg.twist.linear.x, msg.twist.linear.y};
  const double omega = msg.twist.angular.z;
  switch (msg.shape)
  {
    case BodyMsg::DISK:
    {
      require_positive(msg.radius, where, "radius");
      if (!msg.vertices.empty())
      {
        reject(where, "vertices: a DISK takes none (" + std::to_string(msg.vertices.size()) + " given)");
      }
      Body body(msg.mass, msg.radius, position, velocity, omega);
      body.set_theta(msg.pose.theta);
      return body;
    }
    case BodyMsg::POLYGON:
      return Body(msg.mass, outline_from_msg(msg, where), position, velocity, msg.pose.theta, omega);
    default:
      reject(where, "shape = " + std::to_string(msg.shape) + " is not DISK (0) or POLYGON (1)");
  }
}

}  // namespace

void check_pose_and_twist(const geometry_msgs::Pose2D& pose, const geometry_msgs::Twist& twist,
                          const std::string& where)
{
  require_finite(pose.x, where, "pose.x");
  require_finite(pose.y, where, "pose.y");
  require_finite(pose.theta, where, "pose.theta");
  require_finite(twist.linear.x, where, "twist.linear.x");
  require_finite(twist.linear.y, where, "twist.linear.y");
  require_finite(twist.angular.z, where, "twist.angular.z");
}

Material material_from_msg(const BodyMaterial& msg, const std::string& where)
{
  require_in_range(msg.restitution, 0.0, kMaxRestitution, where, "material.restitution");
  require_non_negative(msg.static_friction, where, "material.static_friction");
  require_non_negative(msg.kinetic_friction, where, "material.kinetic_friction");
  return Material{msg.restitution, msg.static_friction, msg.kinetic_friction};
}

BodyMaterial material_to_msg(const Material& material)
{
  BodyMaterial msg;
  msg.restitution = material.restitution;
  msg.static_friction = material.static_friction;
  msg.kinetic_friction = material.kinetic_friction;
  return msg;
}

SceneBody scene_body_from_msg(const BodyMsg& msg, const std::string& where)
{
  require_positive(msg.mass, where, "mass");
  check_pose_and_twist(msg.pose, msg.twist, where);
  const BodyType type = body_type_from_msg(msg.type, where);
  const Material material = material_from_msg(msg.material, where);
  try
  {
    Body body = build_body(msg, where);
    body.set_type(type);
    return SceneBody{body, material, ""};
  }
  catch (const InvalidRequest&)
  {
    throw;
  }
  catch (const std::invalid_argument& e)
  {
    reject(where, e.what());
  }
}

std::vector<SceneBody> scene_bodies_from_msgs(const std::vector<BodyMsg>& msgs, std::size_t max_bodies)
{
  if (msgs.size() > max_bodies)
  {
    reject("bodies", std::to_string(msgs.size()) + " given, more than the limit of " + std::to_string(max_bodies) +
                         " (parameter ~max_bodies)");
  }
  std::vector<SceneBody> bodies;
  bodies.reserve(msgs.size());
  std::vector<Vec2> centres;
  centres.reserve(msgs.size());
  std::vector<std::string> labels;
  labels.reserve(msgs.size());
  for (std::size_t i = 0; i < msgs.size(); ++i)
  {
    labels.push_back(body_label(i, msgs[i].id));
    bodies.push_back(scene_body_from_msg(msgs[i], labels.back()));
    centres.push_back(bodies.back().body.position());
  }
  check_distinct_centres(centres, labels);
  return bodies;
}

std::vector<Body> bodies_from_msgs(const std::vector<BodyMsg>& msgs, std::size_t max_bodies)
{
  std::vector<SceneBody> scene_bodies = scene_bodies_from_msgs(msgs, max_bodies);
  std::unordered_map<std::uint32_t, std::size_t> first_with_id;
  first_with_id.reserve(msgs.size());
  for (std::size_t i = 0; i < msgs.size(); ++i)
  {
    const auto inserted = first_with_id.emplace(msgs[i].id, i);
    if (!inserted.second)
    {
      reject(body_label(i, msgs[i].id), "id repeats that of bodies[" + std::to_string(inserted.first->second) + "]");
    }
  }
  std::vector<Body> bodies;
  bodies.reserve(scene_bodies.size());
  for (SceneBody& scene_body : scene_bodies)
  {
    bodies.push_back(std::move(scene_body.body));
  }
  return bodies;
}

BodyMsg body_to_msg(const Body& body, std::uint32_t id, const Material& material)
{
  BodyMsg msg;
  msg.id = id;
  msg.shape = body.shape() == Shape::Disk ? BodyMsg::DISK : BodyMsg::POLYGON;
  switch (body.type())
  {
    case BodyType::Dynamic:
      msg.type = BodyMsg::DYNAMIC;
      break;
    case BodyType::Static:
      msg.type = BodyMsg::STATIC;
      break;
    case BodyType::Kinematic:
      msg.type = BodyMsg::KINEMATIC;
      break;
  }
  msg.mass = body.mass();
  msg.radius = body.radius();
  msg.vertices.resize(body.vertex_count());
  for (std::size_t i = 0; i < body.vertex_count(); ++i)
  {
    msg.vertices[i].x = body.local_vertices()[i].x;
    msg.vertices[i].y = body.local_vertices()[i].y;
  }
  msg.pose.x = body.position().x;
  msg.pose.y = body.position().y;
  msg.pose.theta = body.theta();
  msg.twist.linear.x = body.velocity().x;
  msg.twist.linear.y = body.velocity().y;
  msg.twist.angular.z = body.omega();
  msg.material = material_to_msg(material);
  return msg;
}

ContactMsg contact_to_msg(const Contact& contact, const ContactImpulse& impulse, std::uint32_t id_a,
                            std::uint32_t id_b)
{
  ContactMsg msg;
  msg.body_a = id_a;
  msg.body_b = id_b;
  msg.point.x = contact.point.x;
  msg.point.y = contact.point.y;
  msg.normal.x = contact.normal.x;
  msg.normal.y = contact.normal.y;
  msg.penetration = contact.penetration;
  msg.normal_impulse = impulse.normal;
  msg.tangent_impulse = impulse.tangent;
  return msg;
}

}  // namespace ros_interface
}  // namespace collision2d
