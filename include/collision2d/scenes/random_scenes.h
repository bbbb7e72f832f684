// Deterministic random scenes of disks and convex polygons arranged in
// multi-contact islands (chains, stars, piles) with slight overlaps: the
// shared input of the solver soak tests and the benchmarks. The same seed
// gives the same draws with every standard library (the distributions are
// mapped here from the raw engine output, not taken from <random>, whose
// mappings differ between implementations); only libm's last-bit differences
// in cos/sin/pow could move a body by round-off.
#pragma once

#include <cstdint>
#include <random>
#include <vector>

#include "collision2d/body.h"

namespace collision2d
{
namespace scenes
{
struct RandomSceneOptions
{
  int min_bodies = 3;                   ///< per scene
  int max_bodies = 10;                  ///< per scene
  double polygon_probability = 0.5;     ///< chance a body is a polygon rather than a disk
  double box_probability = 0.4;         ///< chance a polygon is a rectangle (face-to-face manifolds)
  double face_to_face_probability = 0.5;  ///< chance a polygon is attached face first, not vertex first
  double min_size = 0.2;                ///< smallest disk radius / polygon half extent (m)
  double max_size = 1.0;                ///< largest disk radius / polygon half extent (m)
  double max_overlap = 0.03;            ///< largest overlap at an attachment, fraction of the smaller size
  double base_mass = 1.0;               ///< lightest possible mass (kg)
  double max_mass_ratio = 100.0;        ///< masses are log-uniform in [base, base * ratio]
  double max_speed = 2.0;               ///< m/s
  double max_spin = 2.0;                ///< rad/s
  double second_island_probability = 0.25;  ///< chance the bodies form two far-apart islands
  double static_probability = 0.0;      ///< chance the first body is static (zero velocity)
};

enum class RandomLayout
{
  Chain,  ///< each body touches the one before it
  Star,   ///< one body touched by all the others
  Pile    ///< each body touches a randomly chosen earlier one
};

struct RandomScene
{
  std::vector<Body> bodies;
  double restitution = 0.0;  ///< e for the whole scene, [0, 1]
  double friction = 0.0;     ///< mu for the whole scene, >= 0
  RandomLayout layout = RandomLayout::Chain;
};

/// Every attachment overlaps its parent by construction; bodies may also
/// overlap others they happen to reach, which only adds contacts.
class RandomSceneGenerator
{
public:
  explicit RandomSceneGenerator(std::uint64_t seed, RandomSceneOptions options = RandomSceneOptions{});

  RandomScene next();

  const RandomSceneOptions& options() const { return options_; }

private:
  std::mt19937_64 engine_;
  RandomSceneOptions options_;
};

}  // namespace scenes
}  // namespace collision2d
