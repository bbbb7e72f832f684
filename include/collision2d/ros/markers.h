// rviz markers for a collision2d WorldState.
//
// `world_state_markers` is the plain conversion: one state in, the ADD
// markers that draw it out. `MarkerBuilder` wraps it with the little memory
// rviz needs so that nothing is left behind: markers whose id vanished since
// the last array are DELETEd, and a reset or newly loaded scene starts with
// DELETEALL.
//
// Namespaces (one per kind) and ids (stable per body id, per contact index):
//   bodies      disks as flat CYLINDERs, polygons as filled TRIANGLE_LISTs
//   outlines    polygon outlines (LINE_STRIP)
//   rotation    one radius per disk (LINE_LIST) that turns with the disk
//   contacts    an ARROW per contact point along its normal, length ~ impulse
//   velocities  an ARROW per moving body, length ~ speed (optional)
//   labels      the body id as TEXT_VIEW_FACING (optional)
//
// Only the generated WorldState header is included (not the core library),
// so this file does not depend on the names of the body/contact messages.
#pragma once

#include <cstdint>
#include <map>
#include <set>
#include <string>

#include "collision2d/ros/messages.h"
#include <visualization_msgs/MarkerArray.h>

namespace collision2d
{
namespace ros_interface
{
/// Marker namespaces, one per kind of marker.
namespace marker_ns
{
constexpr const char* kBodies = "bodies";
constexpr const char* kOutlines = "outlines";
constexpr const char* kRotation = "rotation";
constexpr const char* kContacts = "contacts";
constexpr const char* kVelocities = "velocities";
constexpr const char* kLabels = "labels";
}  // namespace marker_ns

struct MarkerOptions
{
  std::string frame_id;  ///< "" = the state's header.frame_id
  bool show_contacts = true;
  bool show_velocities = false;
  bool show_labels = false;

  double disk_thickness = 0.02;      ///< height of the flat disk cylinders (m)
  double line_width = 0.05;          ///< outlines and radius lines (m)
  double impulse_scale = 0.5;        ///< contact arrow length per impulse (m / (N s))
  double min_contact_arrow = 0.15;   ///< shortest contact arrow, so resting contacts show (m)
  double velocity_scale = 0.1;       ///< velocity arrow length per speed (m / (m/s))
  double min_speed = 1e-3;           ///< slower bodies get no velocity arrow (m/s)
  double arrow_width = 0.06;         ///< shaft diameter of the arrows (m)
  double label_height = 0.35;        ///< text height of the id labels (m)
};

/// `state.header` with the frame id the options ask for.
std_msgs::Header marker_header(const WorldState& state, const MarkerOptions& options);

/// The ADD markers that draw `state`, in namespace order bodies, outlines,
/// rotation, contacts, velocities, labels. Pure: same state, same markers.
visualization_msgs::MarkerArray world_state_markers(const WorldState& state, const MarkerOptions& options);

/// `world_state_markers` plus the DELETE/DELETEALL bookkeeping between arrays.
class MarkerBuilder
{
public:
  explicit MarkerBuilder(MarkerOptions options = MarkerOptions());

  /// The markers of `state`, preceded by DELETEs for the ids of the previous
  /// array that are not in this one, or by DELETEALL (per namespace) for the
  /// first array and when the world was reset or replaced since the previous
  /// one (its frame count went back or its scene changed).
  visualization_msgs::MarkerArray build(const WorldState& state);

  const MarkerOptions& options() const { return options_; }

private:
  bool world_replaced(const WorldState& state) const;
  void append_deletes(const visualization_msgs::MarkerArray& current, const std_msgs::Header& header,
                      visualization_msgs::MarkerArray& out) const;
  void remember(const visualization_msgs::MarkerArray& current);

  MarkerOptions options_;
  bool has_previous_ = false;
  std::uint64_t previous_frame_count_ = 0;
  std::string previous_scene_;
  std::map<std::string, std::set<std::int32_t>> previous_ids_;  ///< per namespace
};

}  // namespace ros_interface
}  // namespace collision2d
