// Exact time of impact for translating convex shapes (orientation held fixed).
#pragma once

#include "collision2d/body.h"

namespace collision2d
{
/// Earliest t in [0, 1] at which `a` translated by t * da and `b` translated
/// by t * db first touch: 0 if they already overlap, 1 if they do not touch in
/// (0, 1]. Computed in closed form as a ray cast of the relative displacement
/// against the Minkowski sum of the two outlines; no sampling.
double time_of_impact(const Body& a, Vec2 da, const Body& b, Vec2 db);

}  // namespace collision2d
