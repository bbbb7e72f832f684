// A collision2d::Scene built in Box2D v3 (its C API). Only compiled when the
// build is given COLLISION2D_BOX2D_V3_DIR (see bench/CMakeLists.txt); its
// headers and library never ship with this package.
#pragma once

#include <memory>

#include "../engine.h"

namespace collision2d
{
namespace bench
{
/// Every variant runs on WorldSettings::workers threads (workerCount; above
/// 1, Box2D v3's own scheduler, as no task system is given; every bench
/// leaves it at 1 except the scaling bench's --workers) with Box2D v3's
/// defaults (contact hertz, damping ratio, push-out speed, slop, continuous
/// collision). Defaults: b2World_Step(dt, 4), sleeping on (its
/// recommendation). Matched and Substepped: b2World_Step(dt, substeps),
/// sleeping off; Matched also takes our restitution threshold. Box2D v3 has
/// no velocity-iteration count (one solve and one relax pass per substep)
/// and its linear slop is a compile-time constant, so neither can be matched.
std::unique_ptr<Engine> make_box2d_v3_engine(const Scene& scene, const EngineConfig& config);

}  // namespace bench
}  // namespace collision2d
