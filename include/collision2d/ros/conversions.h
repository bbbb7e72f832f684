// Conversions between the collision2d messages and the core's bodies and
// contacts. Every *_from_msg validates first and throws InvalidRequest naming
// the body (index and id) and the field, so a request either converts whole
// or is rejected before anything is touched.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "collision2d/ros/messages.h"

#include "collision2d/body.h"
#include "collision2d/contact.h"
#include "collision2d/scene.h"
#include "collision2d/world.h"
#include "collision2d/ros/validation.h"

namespace collision2d
{
namespace ros_interface
{
/// Throws InvalidRequest naming `where` and the field when a pose or twist
/// component the interface uses is not finite.
void check_pose_and_twist(const geometry_msgs::Pose2D& pose, const geometry_msgs::Twist& twist,
                          const std::string& where);
Material material_from_msg(const BodyMaterial& msg, const std::string& where);
BodyMaterial material_to_msg(const Material& material);

/// The body and material `msg` describes; `where` names it in error messages.
SceneBody scene_body_from_msg(const BodyMsg& msg, const std::string& where);
/// Every body of a request, in order: at most `max_bodies` of them, each
/// valid, and no two sharing a centre.
std::vector<SceneBody> scene_bodies_from_msgs(const std::vector<BodyMsg>& msgs, std::size_t max_bodies);
/// As above, bodies only, and the ids must also be distinct (responses refer
/// to bodies by id).
std::vector<Body> bodies_from_msgs(const std::vector<BodyMsg>& msgs, std::size_t max_bodies);

BodyMsg body_to_msg(const Body& body, std::uint32_t id, const Material& material = Material());
/// `id_a` and `id_b` are the ids of bodies contact.a and contact.b.
ContactMsg contact_to_msg(const Contact& contact, const ContactImpulse& impulse, std::uint32_t id_a,
                            std::uint32_t id_b);

}  // namespace ros_interface
}  // namespace collision2d
