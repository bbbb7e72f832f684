// A collision2d::Scene built in Box2D 2.4.1.
#pragma once

#include <memory>

#include "../engine.h"

namespace collision2d
{
namespace bench
{
/// Defaults: World::Step(dt, 8, 3) once per frame (the Box2D manual's
/// recommendation), sleeping allowed, restitution threshold 1 m/s. Matched:
/// `substeps` steps of dt/substeps with our velocity iterations (position
/// iterations stay 3: Box2D's position solver plays the part of our position
/// correction), our restitution threshold, sleeping off. Box2D's linear slop
/// (5 mm) is a compile-time constant and cannot be matched. Substepped:
/// `substeps` steps of dt/substeps with the default iterations and
/// restitution threshold, sleeping off.
std::unique_ptr<Engine> make_box2d_engine(const Scene& scene, const EngineConfig& config);

}  // namespace bench
}  // namespace collision2d
