// Exact time of impact for translating convex shapes (orientation held fixed),
// and the first touch of shapes that also turn at a constant rate.
#pragma once

#include "collision2d/body.h"

namespace collision2d
{
/// Earliest t in [0, 1] at which `a` translated by t * da and `b` translated
/// by t * db first touch: 0 if they already overlap, 1 if they do not touch in
/// (0, 1]. Computed in closed form as a ray cast of the relative displacement
/// against the Minkowski sum of the two outlines; no sampling.
double time_of_impact(const Body& a, Vec2 da, const Body& b, Vec2 db);

/// The same for bodies that also turn about their centroids, by t * turn_a
/// and t * turn_b (rad), at a constant rate. Steps that cannot carry either
/// outline through the other (conservative advancement on a lower bound of
/// the gap) find the first overlap; a bracketing search then returns a t at
/// which the pair touches within kRelativeTouchTolerance of its size; 0 if
/// they touch within it already and get deeper. With both turns 0 this is
/// the closed form above.
double time_of_impact(const Body& a, Vec2 da, double turn_a, const Body& b, Vec2 db, double turn_b);

}  // namespace collision2d
