// Marker colours (see marker_colors.h).
#include "collision2d/ros/marker_colors.h"

#include <cmath>

#include "collision2d/ros/messages.h"

namespace collision2d
{
namespace ros_interface
{
namespace
{
using BodyMsgT = WorldState::_bodies_type::value_type;

constexpr float kStaticGrey = 0.55F;
constexpr float kKinematicRgb[] = {0.25F, 0.45F, 0.95F};  // blue
constexpr float kContactRgb[] = {1.0F, 0.2F, 1.0F};       // magenta
constexpr float kVelocityRgb[] = {0.2F, 0.9F, 1.0F};      // cyan
constexpr float kOpaque = 1.0F;
// Dynamic hues cover red through green only (hue fraction of the colour
// wheel), leaving blue to kinematic bodies. Stepping by the golden ratio puts
// consecutive ids far apart on that arc.
constexpr double kDynamicHueSpan = 0.45;
constexpr double kGoldenRatioFraction = 0.6180339887498949;
constexpr float kDynamicSaturation = 0.75F;
constexpr float kDynamicValue = 0.95F;

std_msgs::ColorRGBA rgba(float r, float g, float b, float a = kOpaque)
{
  std_msgs::ColorRGBA color;
  color.r = r;
  color.g = g;
  color.b = b;
  color.a = a;
  return color;
}

/// HSV to RGB with hue in [0, 1).
std_msgs::ColorRGBA from_hsv(double hue, float saturation, float value)
{
  constexpr int kSectors = 6;
  const double h = hue * kSectors;
  const int sector = static_cast<int>(std::floor(h)) % kSectors;
  const float f = static_cast<float>(h - std::floor(h));
  const float p = value * (1.0F - saturation);
  const float q = value * (1.0F - saturation * f);
  const float t = value * (1.0F - saturation * (1.0F - f));
  switch (sector)
  {
    case 0: return rgba(value, t, p);
    case 1: return rgba(q, value, p);
    case 2: return rgba(p, value, t);
    case 3: return rgba(p, q, value);
    case 4: return rgba(t, p, value);
    default: return rgba(value, p, q);
  }
}

std_msgs::ColorRGBA dynamic_color(std::uint32_t id)
{
  const double step = std::fmod(static_cast<double>(id) * kGoldenRatioFraction, 1.0);
  return from_hsv(kDynamicHueSpan * step, kDynamicSaturation, kDynamicValue);
}

}  // namespace

std_msgs::ColorRGBA body_color(std::uint8_t type, std::uint32_t id)
{
  switch (type)
  {
    case BodyMsgT::STATIC: return rgba(kStaticGrey, kStaticGrey, kStaticGrey);
    case BodyMsgT::KINEMATIC: return rgba(kKinematicRgb[0], kKinematicRgb[1], kKinematicRgb[2]);
    default: return dynamic_color(id);
  }
}

std_msgs::ColorRGBA shaded(std_msgs::ColorRGBA color, float factor)
{
  color.r *= factor;
  color.g *= factor;
  color.b *= factor;
  return color;
}

std_msgs::ColorRGBA contact_color()
{
  return rgba(kContactRgb[0], kContactRgb[1], kContactRgb[2]);
}

std_msgs::ColorRGBA velocity_color()
{
  return rgba(kVelocityRgb[0], kVelocityRgb[1], kVelocityRgb[2]);
}

std_msgs::ColorRGBA label_color()
{
  return rgba(kOpaque, kOpaque, kOpaque);  // white
}

}  // namespace ros_interface
}  // namespace collision2d
