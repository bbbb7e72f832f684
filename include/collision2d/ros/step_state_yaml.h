// The World's step state (contacts with their impulses, the substep they were
// made over, sleep) as YAML keys of a snapshot's clock document, written so
// every number reads back exactly.
#pragma once

#include <ostream>
#include <string>

#include <yaml-cpp/yaml.h>

#include "collision2d/world.h"

namespace collision2d
{
namespace ros_interface
{
/// The keys write_step_state writes; a snapshot without them (an older
/// file) restores with a cold start.
extern const char* const kStepStateKeys[4];

void write_step_state(std::ostream& out, const StepState& state);
/// Reads the keys when present (an empty state otherwise). Throws
/// std::runtime_error "source: snapshot: ..." naming the bad key or entry.
StepState read_step_state(const YAML::Node& doc, const std::string& source);

}  // namespace ros_interface
}  // namespace collision2d
