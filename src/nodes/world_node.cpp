// The collision2d world node: services, world_state topic, parameters and
// dynamic_reconfigure are all in collision2d::ros_interface::WorldNode.
#include <ros/ros.h>

#include "collision2d/ros/world_node.h"

int main(int argc, char** argv)
{
  ros::init(argc, argv, "world");
  collision2d::ros_interface::WorldNode node(ros::NodeHandle(), ros::NodeHandle("~"));
  node.spin();
  return 0;
}
