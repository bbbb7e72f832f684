// The stacks compared with Box2D v3: the same scenes for every
// engine, described so anyone can rebuild them in any engine. Unit boxes of
// 1 kg (1 m x 1 m), friction 0.6 (static and kinetic), restitution 0, a
// static ground 200 m x 1 m with its top at y = 0, exactly touching boxes,
// gravity -10 m/s^2, dt 1/60 s, 4 substeps, sleeping off, every other
// setting the engine's default.
#pragma once

#include <string>
#include <vector>

#include "bench_scenes.h"

namespace collision2d
{
namespace bench
{
/// Stack drift is measured from this time on (s).
constexpr double kStackSettleSeconds = 1.0;

/// stack_pyramid_20, stack_column_20, stack_column_20_nudged (its top box
/// 1 um off centre), stack_pyramid_60, stack_pyramid_100.
std::vector<std::string> stack_scene_names();
/// Whether `name` is one of stack_scene_names().
bool is_stack_scene(const std::string& name);
/// Throws std::invalid_argument for a name not in stack_scene_names().
BenchScene make_stack_scene(const std::string& name);

/// Throughput scenes under the same rules, about `bodies` dynamic bodies:
/// "pyramid" (the largest pyramid with at most that many boxes) and "rain"
/// (scene_parts.h: disks and boxes falling onto the ground). The ground grows
/// to fit. Throws std::invalid_argument for another kind.
Scene make_throughput_scene(const std::string& kind, long bodies);

}  // namespace bench
}  // namespace collision2d
