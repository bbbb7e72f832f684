// A collision2d::Scene built in Chipmunk 7.
#pragma once

#include <memory>

#include "../engine.h"

namespace collision2d
{
namespace bench
{
/// Defaults: cpSpaceStep(dt) once per frame with Chipmunk's defaults
/// (10 iterations, collision slop 0.1 m, no sleeping). Matched: `substeps`
/// steps of dt/substeps, our velocity iterations and our slop. Substepped:
/// `substeps` steps of dt/substeps with the defaults. Chipmunk has
/// no continuous collision, so fast bodies may tunnel in both variants.
std::unique_ptr<Engine> make_chipmunk_engine(const Scene& scene, const EngineConfig& config);

}  // namespace bench
}  // namespace collision2d
