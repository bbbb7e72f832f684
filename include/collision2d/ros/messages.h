// The one way ROS code in this package includes the generated message and
// service headers.
//
// catkin generates the C++ types of a package's messages in a namespace named
// after the package, so msg/Body.msg and msg/Contact.msg become
// collision2d::Body and collision2d::Contact: the same names as the core's
// classes. The message *templates* (collision2d::Body_<Alloc>) do not clash,
// only the two typedefs do, so they are renamed here to collision2d::BodyMsg
// and collision2d::ContactMsg while the generated headers are read. Their
// pointer typedefs keep their generated names (BodyPtr, ContactConstPtr, ...).
// A node that never includes the core can include the generated headers
// directly and use collision2d::Body as the message.
#pragma once

// Everything the generated headers pull in, read first and without the
// renaming below, so only the generated headers see it.
#include <ros/builtin_message_traits.h>
#include <ros/message_operations.h>
#include <ros/serialization.h>
#include <ros/service_traits.h>
#include <ros/types.h>

#include <geometry_msgs/Point.h>
#include <geometry_msgs/Pose2D.h>
#include <geometry_msgs/Twist.h>
#include <geometry_msgs/Vector3.h>
#include <std_msgs/Header.h>

#ifdef Body
#error "collision2d/ros/messages.h: a macro named Body is already defined"
#endif
#ifdef Contact
#error "collision2d/ros/messages.h: a macro named Contact is already defined"
#endif
#define Body BodyMsg
#define Contact ContactMsg

#include <collision2d/Body.h>
#include <collision2d/BodyMaterial.h>
#include <collision2d/Contact.h>
#include <collision2d/Effects.h>
#include <collision2d/SolverReport.h>
#include <collision2d/SolverSettings.h>
#include <collision2d/StepSummary.h>
#include <collision2d/WorldConfig.h>
#include <collision2d/WorldState.h>

#include <collision2d/AddBody.h>
#include <collision2d/GetWorld.h>
#include <collision2d/LoadScene.h>
#include <collision2d/LoadWorld.h>
#include <collision2d/RemoveBody.h>
#include <collision2d/ResolveContacts.h>
#include <collision2d/SaveWorld.h>
#include <collision2d/SetBodyState.h>
#include <collision2d/SetWorld.h>
#include <collision2d/StepWorld.h>

#undef Body
#undef Contact
