// WorldState -> ADD markers, one namespace per kind (see markers.h).
#include "collision2d/ros/markers.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

#include <geometry_msgs/Point.h>
#include <std_msgs/ColorRGBA.h>

#include "collision2d/ros/marker_colors.h"

namespace collision2d
{
namespace ros_interface
{
namespace
{
// Element types through WorldState, so renaming the message files does not
// touch this file.
using BodyMsgT = WorldState::_bodies_type::value_type;
using ContactMsgT = WorldState::_contacts_type::value_type;
using visualization_msgs::Marker;

// Drawing heights (m) for the top-down view: later layers are drawn above
// earlier ones, so lines and arrows are never hidden inside a filled body.
constexpr double kFillZ = 0.0;
constexpr double kLineZ = 0.05;
constexpr double kArrowZ = 0.1;
constexpr double kLabelZ = 0.15;
// Arrow head diameter and length as multiples of the shaft diameter.
constexpr double kArrowHeadWidthFactor = 2.5;
constexpr double kArrowHeadLengthFactor = 3.0;
// Lines (polygon outlines, disk radii) are drawn darker than the fill, so
// touching bodies of one colour stay distinguishable.
constexpr float kLineShade = 0.45F;

Marker make_marker(const std_msgs::Header& header, const char* ns, std::int32_t id, std::int32_t type)
{
  Marker marker;
  marker.header = header;
  marker.ns = ns;
  marker.id = id;
  marker.type = type;
  marker.action = Marker::ADD;
  marker.pose.orientation.w = 1.0;
  marker.scale.x = marker.scale.y = marker.scale.z = 1.0;
  return marker;
}

std::int32_t body_marker_id(const BodyMsgT& body)
{
  return static_cast<std::int32_t>(body.id);
}

geometry_msgs::Point point(double x, double y, double z)
{
  geometry_msgs::Point p;
  p.x = x;
  p.y = y;
  p.z = z;
  return p;
}

/// The body's planar pose (centroid, rotation about +z) lifted to height z.
void set_pose(const BodyMsgT& body, double z, Marker& marker)
{
  marker.pose.position = point(body.pose.x, body.pose.y, z);
  marker.pose.orientation.x = 0.0;
  marker.pose.orientation.y = 0.0;
  marker.pose.orientation.z = std::sin(0.5 * body.pose.theta);
  marker.pose.orientation.w = std::cos(0.5 * body.pose.theta);
}

Marker disk_fill(const std_msgs::Header& header, const BodyMsgT& body, const MarkerOptions& options)
{
  Marker marker = make_marker(header, marker_ns::kBodies, body_marker_id(body), Marker::CYLINDER);
  set_pose(body, kFillZ, marker);
  marker.scale.x = marker.scale.y = 2.0 * body.radius;
  marker.scale.z = options.disk_thickness;
  marker.color = body_color(body.type, body.id);
  return marker;
}

/// Fan triangulation from the first vertex: exact for the convex outlines the
/// messages carry.
Marker polygon_fill(const std_msgs::Header& header, const BodyMsgT& body)
{
  Marker marker = make_marker(header, marker_ns::kBodies, body_marker_id(body), Marker::TRIANGLE_LIST);
  set_pose(body, kFillZ, marker);
  const auto& v = body.vertices;
  for (std::size_t i = 1; i + 1 < v.size(); ++i)
  {
    marker.points.push_back(point(v[0].x, v[0].y, 0.0));
    marker.points.push_back(point(v[i].x, v[i].y, 0.0));
    marker.points.push_back(point(v[i + 1].x, v[i + 1].y, 0.0));
  }
  marker.color = body_color(body.type, body.id);
  return marker;
}

Marker polygon_outline(const std_msgs::Header& header, const BodyMsgT& body, const MarkerOptions& options)
{
  Marker marker = make_marker(header, marker_ns::kOutlines, body_marker_id(body), Marker::LINE_STRIP);
  set_pose(body, kLineZ, marker);
  for (const auto& vertex : body.vertices)
  {
    marker.points.push_back(point(vertex.x, vertex.y, 0.0));
  }
  if (!body.vertices.empty())
  {
    marker.points.push_back(marker.points.front());  // close the loop
  }
  marker.scale.x = options.line_width;
  marker.color = shaded(body_color(body.type, body.id), kLineShade);
  return marker;
}

/// A radius along the disk's body x axis: it turns as the disk spins.
Marker disk_rotation(const std_msgs::Header& header, const BodyMsgT& body, const MarkerOptions& options)
{
  Marker marker = make_marker(header, marker_ns::kRotation, body_marker_id(body), Marker::LINE_LIST);
  set_pose(body, kLineZ, marker);
  marker.points.push_back(point(0.0, 0.0, 0.0));
  marker.points.push_back(point(body.radius, 0.0, 0.0));
  marker.scale.x = options.line_width;
  marker.color = shaded(body_color(body.type, body.id), kLineShade);
  return marker;
}

Marker arrow(const std_msgs::Header& header, const char* ns, std::int32_t id, const geometry_msgs::Point& from,
             double dx, double dy, const MarkerOptions& options)
{
  Marker marker = make_marker(header, ns, id, Marker::ARROW);
  marker.points.push_back(point(from.x, from.y, kArrowZ));
  marker.points.push_back(point(from.x + dx, from.y + dy, kArrowZ));
  marker.scale.x = options.arrow_width;
  marker.scale.y = kArrowHeadWidthFactor * options.arrow_width;
  marker.scale.z = kArrowHeadLengthFactor * options.arrow_width;
  return marker;
}

/// Points along +normal, the direction the impulse pushes body_b.
Marker contact_arrow(const std_msgs::Header& header, std::int32_t id, const ContactMsgT& contact,
                     const MarkerOptions& options)
{
  const double length = std::max(options.min_contact_arrow, options.impulse_scale * contact.normal_impulse);
  Marker marker = arrow(header, marker_ns::kContacts, id, contact.point, length * contact.normal.x,
                        length * contact.normal.y, options);
  marker.color = contact_color();
  return marker;
}

geometry_msgs::Point centroid(const BodyMsgT& body)
{
  return point(body.pose.x, body.pose.y, 0.0);
}

Marker velocity_arrow(const std_msgs::Header& header, const BodyMsgT& body, const MarkerOptions& options)
{
  const double s = options.velocity_scale;
  Marker marker = arrow(header, marker_ns::kVelocities, body_marker_id(body), centroid(body),
                        s * body.twist.linear.x, s * body.twist.linear.y, options);
  marker.color = velocity_color();
  return marker;
}

Marker label(const std_msgs::Header& header, const BodyMsgT& body, const MarkerOptions& options)
{
  Marker marker = make_marker(header, marker_ns::kLabels, body_marker_id(body), Marker::TEXT_VIEW_FACING);
  marker.pose.position = point(body.pose.x, body.pose.y, kLabelZ);
  marker.scale.z = options.label_height;
  marker.text = std::to_string(body.id);
  marker.color = label_color();
  return marker;
}

bool is_moving(const BodyMsgT& body, double min_speed)
{
  return std::hypot(body.twist.linear.x, body.twist.linear.y) >= min_speed;
}

using Markers = std::vector<Marker>;

void append_fills(const std_msgs::Header& header, const WorldState& state, const MarkerOptions& options,
                  Markers& out)
{
  for (const auto& body : state.bodies)
  {
    const bool disk = body.shape == BodyMsgT::DISK;
    out.push_back(disk ? disk_fill(header, body, options) : polygon_fill(header, body));
  }
}

void append_outlines(const std_msgs::Header& header, const WorldState& state, const MarkerOptions& options,
                     Markers& out)
{
  for (const auto& body : state.bodies)
  {
    if (body.shape != BodyMsgT::DISK)
    {
      out.push_back(polygon_outline(header, body, options));
    }
  }
}

void append_rotations(const std_msgs::Header& header, const WorldState& state, const MarkerOptions& options,
                      Markers& out)
{
  for (const auto& body : state.bodies)
  {
    if (body.shape == BodyMsgT::DISK)
    {
      out.push_back(disk_rotation(header, body, options));
    }
  }
}

/// Contact ids are indices into state.contacts: contacts have no identity of
/// their own between steps.
void append_contacts(const std_msgs::Header& header, const WorldState& state, const MarkerOptions& options,
                     Markers& out)
{
  for (std::size_t i = 0; i < state.contacts.size(); ++i)
  {
    out.push_back(contact_arrow(header, static_cast<std::int32_t>(i), state.contacts[i], options));
  }
}

void append_velocities(const std_msgs::Header& header, const WorldState& state, const MarkerOptions& options,
                       Markers& out)
{
  for (const auto& body : state.bodies)
  {
    if (body.type != BodyMsgT::STATIC && is_moving(body, options.min_speed))
    {
      out.push_back(velocity_arrow(header, body, options));
    }
  }
}

void append_labels(const std_msgs::Header& header, const WorldState& state, const MarkerOptions& options,
                   Markers& out)
{
  for (const auto& body : state.bodies)
  {
    out.push_back(label(header, body, options));
  }
}

}  // namespace

std_msgs::Header marker_header(const WorldState& state, const MarkerOptions& options)
{
  std_msgs::Header header = state.header;
  if (!options.frame_id.empty())
  {
    header.frame_id = options.frame_id;
  }
  return header;
}

visualization_msgs::MarkerArray world_state_markers(const WorldState& state, const MarkerOptions& options)
{
  const std_msgs::Header header = marker_header(state, options);
  visualization_msgs::MarkerArray out;
  append_fills(header, state, options, out.markers);
  append_outlines(header, state, options, out.markers);
  append_rotations(header, state, options, out.markers);
  if (options.show_contacts)
  {
    append_contacts(header, state, options, out.markers);
  }
  if (options.show_velocities)
  {
    append_velocities(header, state, options, out.markers);
  }
  if (options.show_labels)
  {
    append_labels(header, state, options, out.markers);
  }
  return out;
}

}  // namespace ros_interface
}  // namespace collision2d
