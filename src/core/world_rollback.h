// Internal to the core: what a step keeps aside so that a failed step puts
// the World back exactly as it was (world_rollback.cpp keeps and restores it;
// world_sleeping_contacts.cpp keeps what sleeping changes). Kept across
// steps: no allocation per step once warmed up.
#pragma once

#include <cstdint>
#include <vector>

#include "collision2d/world.h"
#include "contact_kernel.h"

namespace collision2d
{
namespace detail
{
/// Names a sleeping island. 64 bits never run out: a million new islands a
/// second would take 580,000 years. 32 bits wrapped after 20 hours of 1000
/// islands falling asleep each 60 Hz frame, and then two islands shared a label.
using IslandLabel = std::uint64_t;

/// Each body's pose and velocity, what a failed step puts back.
struct BodyMotion
{
  Vec2 position;
  double theta = 0.0;
  Vec2 velocity;
  double omega = 0.0;
};

/// The World's state before the step, as far as the step has changed it.
struct Rollback
{
  bool active = false;       ///< inside a step that keeps what it changes
  bool movers_only = false;  ///< only the movers' motion is kept so far
  std::vector<BodyMotion> motion;
  std::vector<unsigned char> asleep;
  std::vector<double> rest_time;
  std::vector<WorldContact> contacts;  ///< unless contacts_in_place
  bool contacts_in_place = false;      ///< the step's contacts before it stay in contacts_ until its one publish
  /// ... which has happened: they are gone. The overflow check comes before
  /// it, so only running out of memory after it (update_sleep) finds them gone.
  bool contacts_published = false;
  bool sleeping_kept = false;          ///< the step changed what sleeps; the state before is kept below
  std::vector<WorldContact> sleeping_contacts;
  double sleeping_penetration = 0.0;
  std::vector<IslandLabel> island_label;
  IslandLabel next_island_label = 0;
  ContactPoints points;  ///< only when a prediction reads them next step
  bool clamping = false;     ///< a body stopped at its time of impact in the last substep ...
  std::vector<double> toi;   ///< ... and each body's fraction of it, when one did
  double cache_h = 0.0;
  double time = 0.0;
  std::uint64_t frame_count = 0;
};

}  // namespace detail
}  // namespace collision2d
