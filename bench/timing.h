// Wall-clock helpers shared by the benchmarks.
#pragma once

#include <vector>

#include "engine.h"

namespace collision2d
{
namespace bench
{
/// Frames in `seconds` of frames of `dt` (at least one).
int frames_for(double seconds, double dt);
/// Median of the values (the mean of the middle two for an even count).
double median(std::vector<double> values);
/// Mean wall time of one frame (ms) over `frames` frames, by steady_clock.
double time_frames(Engine& engine, int frames);

}  // namespace bench
}  // namespace collision2d
