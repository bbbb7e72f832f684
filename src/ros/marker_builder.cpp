// MarkerBuilder: world_state_markers plus DELETE/DELETEALL between arrays, so
// rviz shows no ghosts of removed bodies, finished contacts or old scenes.
#include <utility>

#include "collision2d/ros/markers.h"

namespace collision2d
{
namespace ros_interface
{
namespace
{
using visualization_msgs::Marker;

constexpr const char* kAllNamespaces[] = {marker_ns::kBodies,   marker_ns::kOutlines,   marker_ns::kRotation,
                                          marker_ns::kContacts, marker_ns::kVelocities, marker_ns::kLabels};

Marker delete_marker(const std_msgs::Header& header, const std::string& ns, std::int32_t id, std::int32_t action)
{
  Marker marker;
  marker.header = header;
  marker.ns = ns;
  marker.id = id;
  marker.action = action;
  marker.pose.orientation.w = 1.0;
  return marker;
}

}  // namespace

MarkerBuilder::MarkerBuilder(MarkerOptions options) : options_(std::move(options))
{
}

visualization_msgs::MarkerArray MarkerBuilder::build(const WorldState& state)
{
  visualization_msgs::MarkerArray current = world_state_markers(state, options_);
  const std_msgs::Header header = marker_header(state, options_);

  visualization_msgs::MarkerArray out;
  if (!has_previous_ || world_replaced(state))
  {
    // The first array clears what an earlier run of the node left in rviz.
    // One DELETEALL per namespace, all before any ADD, works whether rviz
    // scopes DELETEALL to the marker's namespace or to the whole display.
    for (const char* ns : kAllNamespaces)
    {
      out.markers.push_back(delete_marker(header, ns, 0, Marker::DELETEALL));
    }
  }
  else
  {
    append_deletes(current, header, out);
  }
  out.markers.insert(out.markers.end(), current.markers.begin(), current.markers.end());

  remember(current);
  has_previous_ = true;
  previous_frame_count_ = state.frame_count;
  previous_scene_ = state.scene;
  return out;
}

bool MarkerBuilder::world_replaced(const WorldState& state) const
{
  return has_previous_ && (state.frame_count < previous_frame_count_ || state.scene != previous_scene_);
}

void MarkerBuilder::append_deletes(const visualization_msgs::MarkerArray& current, const std_msgs::Header& header,
                                   visualization_msgs::MarkerArray& out) const
{
  std::map<std::string, std::set<std::int32_t>> current_ids;
  for (const auto& marker : current.markers)
  {
    current_ids[marker.ns].insert(marker.id);
  }
  for (const auto& entry : previous_ids_)
  {
    const std::set<std::int32_t>& still_there = current_ids[entry.first];
    for (std::int32_t id : entry.second)
    {
      if (still_there.count(id) == 0)
      {
        out.markers.push_back(delete_marker(header, entry.first, id, Marker::DELETE));
      }
    }
  }
}

void MarkerBuilder::remember(const visualization_msgs::MarkerArray& current)
{
  previous_ids_.clear();
  for (const auto& marker : current.markers)
  {
    previous_ids_[marker.ns].insert(marker.id);
  }
}

}  // namespace ros_interface
}  // namespace collision2d
