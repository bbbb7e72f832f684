// How close to touching counts as touching once bodies have been moved to an
// exact time of impact.
#pragma once

namespace collision2d
{
/// Relative tolerance, scaled by the sum of a pair's radii (m per m). Moving
/// bodies to the time of impact leaves the impacting pair touching only up to
/// round-off, so step() counts pairs whose gap is within this fraction of their
/// size as touching contacts, and time_of_impact() treats an overlap shallower
/// than it as touching rather than overlapping (otherwise a pair resolved at t*
/// would report t = 0 on every following step). 1e-9 is far above the
/// round-off of p + t v and far below any gap that matters physically.
constexpr double kRelativeTouchTolerance = 1e-9;

}  // namespace collision2d
