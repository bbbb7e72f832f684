// The stateless ResolveContacts handler. It touches no shared state, so any
// number of service threads may run it at once without a lock.
#pragma once

#include <cstddef>

#include "collision2d/ros/messages.h"

namespace collision2d
{
namespace ros_interface
{
/// Serves one request and never throws: bad input gives success = false and
/// a message naming the body (index and id) or settings field, with nothing
/// else filled in. `node_settings` stand in for the request's settings when
/// it sets use_node_settings.
void resolve_contacts(const ResolveContacts::Request& request, const SolverSettings& node_settings,
                      std::size_t max_bodies, ResolveContacts::Response& response);

}  // namespace ros_interface
}  // namespace collision2d
