// Text the nodes put in service messages and logs: printable, whatever bytes
// a scene file or a request held.
#pragma once

#include <string>

#include "collision2d/world_settings.h"

namespace collision2d
{
namespace ros_interface
{
/// `text` as valid UTF-8 without control characters: other bytes are written
/// \xNN, tabs and newlines kept, and a NaN's "-nan" becomes "nan".
std::string printable_text(const std::string& text);

/// One line of the main world settings (dt, substeps, iterations, gravity) for logs.
std::string settings_summary(const WorldSettings& settings);

}  // namespace ros_interface
}  // namespace collision2d
