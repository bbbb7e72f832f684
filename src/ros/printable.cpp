// printable_text and settings_summary.
#include "collision2d/ros/printable.h"

#include <cstdio>

#include "collision2d/ros/validation.h"

namespace collision2d
{
namespace ros_interface
{
namespace
{
/// Length of the valid UTF-8 sequence starting at text[i], or 0 when the
/// bytes there are not one (stray continuation, overlong, surrogate, > U+10FFFF).
std::size_t utf8_length(const std::string& text, std::size_t i)
{
  const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(text[k]); };
  const unsigned char lead = byte(i);
  std::size_t length = 0;
  unsigned char min_second = 0x80;
  unsigned char max_second = 0xBF;
  if (lead >= 0xC2 && lead <= 0xDF)
  {
    length = 2;
  }
  else if (lead >= 0xE0 && lead <= 0xEF)
  {
    length = 3;
    min_second = lead == 0xE0 ? 0xA0 : 0x80;
    max_second = lead == 0xED ? 0x9F : 0xBF;
  }
  else if (lead >= 0xF0 && lead <= 0xF4)
  {
    length = 4;
    min_second = lead == 0xF0 ? 0x90 : 0x80;
    max_second = lead == 0xF4 ? 0x8F : 0xBF;
  }
  if (length == 0 || i + length > text.size() || byte(i + 1) < min_second || byte(i + 1) > max_second)
  {
    return 0;
  }
  for (std::size_t k = i + 2; k < i + length; ++k)
  {
    if (byte(k) < 0x80 || byte(k) > 0xBF)
    {
      return 0;
    }
  }
  return length;
}

void replace_all(std::string& text, const std::string& from, const std::string& to)
{
  for (std::size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size()))
  {
    text.replace(at, from.size(), to);
  }
}

}  // namespace

std::string printable_text(const std::string& text)
{
  std::string out;
  out.reserve(text.size());
  for (std::size_t i = 0; i < text.size();)
  {
    const unsigned char c = static_cast<unsigned char>(text[i]);
    if (c == '\n' || c == '\t' || (c >= 0x20 && c < 0x7F))
    {
      out += static_cast<char>(c);
      ++i;
      continue;
    }
    const std::size_t length = c >= 0x80 ? utf8_length(text, i) : 0;
    if (length > 0)
    {
      out.append(text, i, length);
      i += length;
      continue;
    }
    char escaped[5];
    std::snprintf(escaped, sizeof escaped, "\\x%02X", c);
    out += escaped;
    ++i;
  }
  // printf and std::to_string write a NaN with its sign bit as "-nan"; a NaN has no sign worth showing.
  replace_all(out, "-nan", "nan");
  return out;
}

std::string settings_summary(const WorldSettings& settings)
{
  return "dt " + format_number(settings.dt) + " s, " + std::to_string(settings.substeps) + " substeps, " +
         std::to_string(settings.velocity_iterations) + " velocity and " +
         std::to_string(settings.position_iterations) + " position iterations, gravity (" +
         format_number(settings.gravity.x) + ", " + format_number(settings.gravity.y) + ") m/s^2";
}

}  // namespace ros_interface
}  // namespace collision2d
