// What rviz would show after a sequence of MarkerArrays, for the marker tests:
// ADD inserts or replaces (ns, id), DELETE removes it, DELETEALL removes its
// namespace (the narrower reading of DELETEALL, so a test passing here also
// passes where rviz clears the whole display). Plus the geometry helpers the
// tests use to put marker points into the world frame.
#pragma once

#include <cmath>
#include <cstddef>
#include <map>
#include <string>
#include <utility>

#include <geometry_msgs/Point.h>
#include <visualization_msgs/MarkerArray.h>

namespace collision2d
{
namespace test
{
class MarkerModel
{
public:
  using Key = std::pair<std::string, int>;

  void apply(const visualization_msgs::MarkerArray& array)
  {
    for (const auto& marker : array.markers)
    {
      apply(marker);
    }
  }

  void apply(const visualization_msgs::Marker& marker)
  {
    using visualization_msgs::Marker;
    if (marker.action == Marker::ADD)
    {
      shown_[{marker.ns, marker.id}] = marker;
    }
    else if (marker.action == Marker::DELETE)
    {
      shown_.erase({marker.ns, marker.id});
    }
    else if (marker.action == Marker::DELETEALL)
    {
      for (auto it = shown_.begin(); it != shown_.end();)
      {
        it = it->first.first == marker.ns ? shown_.erase(it) : std::next(it);
      }
    }
  }

  std::size_t count(const std::string& ns) const
  {
    std::size_t n = 0;
    for (const auto& entry : shown_)
    {
      n += entry.first.first == ns ? 1 : 0;
    }
    return n;
  }

  /// nullptr when (ns, id) is not shown.
  const visualization_msgs::Marker* find(const std::string& ns, int id) const
  {
    const auto it = shown_.find({ns, id});
    return it == shown_.end() ? nullptr : &it->second;
  }

  std::size_t size() const { return shown_.size(); }

private:
  std::map<Key, visualization_msgs::Marker> shown_;
};

struct Point2
{
  double x;
  double y;
};

/// Rotation of a marker about +z (the only rotation 2D markers have).
inline double marker_yaw(const visualization_msgs::Marker& marker)
{
  return 2.0 * std::atan2(marker.pose.orientation.z, marker.pose.orientation.w);
}

/// Marker point `p` (in the marker's pose frame) in the world frame.
inline Point2 to_world(const visualization_msgs::Marker& marker, const geometry_msgs::Point& p)
{
  const double yaw = marker_yaw(marker);
  const double c = std::cos(yaw);
  const double s = std::sin(yaw);
  return {marker.pose.position.x + c * p.x - s * p.y, marker.pose.position.y + s * p.x + c * p.y};
}

/// Body-frame point `local` of a body at (x, y, theta), in the world frame.
inline Point2 place(Point2 local, double x, double y, double theta)
{
  const double c = std::cos(theta);
  const double s = std::sin(theta);
  return {x + c * local.x - s * local.y, y + s * local.x + c * local.y};
}

}  // namespace test
}  // namespace collision2d
