// Colours of the rviz markers: bodies by type (static grey, kinematic blue,
// each dynamic body its own warm-to-green hue), and fixed colours for the
// contact arrows, velocity arrows and labels.
#pragma once

#include <cstdint>

#include <std_msgs/ColorRGBA.h>

namespace collision2d
{
namespace ros_interface
{
/// `type` is the body message's DYNAMIC, STATIC or KINEMATIC; `id` the body id.
/// Dynamic colours are saturated and never blue, so they read apart from the
/// grey static and blue kinematic bodies; ids next to each other (neighbours
/// in the shipped scenes) get hues far apart.
std_msgs::ColorRGBA body_color(std::uint8_t type, std::uint32_t id);

/// `color` with r, g, b multiplied by `factor` (alpha kept).
std_msgs::ColorRGBA shaded(std_msgs::ColorRGBA color, float factor);

std_msgs::ColorRGBA contact_color();
std_msgs::ColorRGBA velocity_color();
std_msgs::ColorRGBA label_color();

}  // namespace ros_interface
}  // namespace collision2d
