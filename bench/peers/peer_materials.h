// How a scene's materials and shapes are handed to the peers so that every
// engine simulates the same effective physics.
//
// Mixing. Ours combines two bodies' coefficients by min. Box2D combines
// friction by sqrt(f1 f2) and restitution by max(e1, e2); Chipmunk multiplies
// both. We give each body the value whose self-mix is its own coefficient:
// Box2D gets (mu, e), Chipmunk gets (sqrt(mu), sqrt(e)). A pair of bodies of
// the same material then sees exactly our coefficient in every engine. The
// shipped scenes give every body that touches another the same material, so
// every touching pair matches; mismatched_material_pairs() counts the pairs
// of different materials in a scene so a benchmark can warn otherwise.
//
// Friction. The peers have one friction coefficient; we give them mu_s, the
// bound that decides whether a resting body holds (stacks, the incline at
// rest). Scenes where bodies slide use mu_s = mu_k.
#pragma once

#include <cstddef>
#include <vector>

#include "collision2d/scene.h"

namespace collision2d
{
namespace bench
{
enum class MixingRule
{
  Box2d,     ///< friction sqrt(f1 f2), restitution max(e1, e2)
  Chipmunk,  ///< friction f1 f2, elasticity e1 e2
};

struct PeerCoefficients
{
  double friction = 0.0;
  double restitution = 0.0;
};

PeerCoefficients peer_coefficients(const Material& material, MixingRule rule);

/// Pairs of non-static bodies (or a body and a static one) with different
/// materials: those pairs would not see our min in a peer.
std::size_t mismatched_material_pairs(const Scene& scene);

/// A convex counter-clockwise polygon with every face moved inward by
/// `distance` (m). Box2D rounds polygons by a skin radius; the inset outline
/// plus the skin covers the original outline up to rounded corners.
std::vector<Vec2> inset_polygon(const std::vector<Vec2>& vertices, double distance);

}  // namespace bench
}  // namespace collision2d
