// The collision2d marker node: world_state -> rviz markers, see
// collision2d::ros_interface::MarkerNode.
#include <ros/ros.h>

#include "collision2d/ros/marker_node.h"

int main(int argc, char** argv)
{
  ros::init(argc, argv, "markers");
  collision2d::ros_interface::MarkerNode node(ros::NodeHandle(), ros::NodeHandle("~"));
  ros::spin();
  return 0;
}
