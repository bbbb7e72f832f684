// The scenes the sweep benchmark runs, each with what "correct" means for it.
#pragma once

#include <string>
#include <vector>

#include "collision2d/scene.h"

namespace collision2d
{
namespace bench
{
/// Which accuracy metric is the scene's main error (the Pareto axis).
enum class SceneKind
{
  Resting,       ///< stacks: drift of the bodies after they settle (m)
  Conservative,  ///< e = 1, mu = 0, no gravity: relative kinetic energy error
  Bounce,        ///< disks dropped on the ground: |measured e - e|
  Incline,       ///< box on a slope: |measured - analytic acceleration| (m/s^2)
  Bullet         ///< fast disk at a thin wall: 1 if it passed through, else 0
};

struct BenchScene
{
  std::string name;
  Scene scene;
  SceneKind kind = SceneKind::Resting;
  double seconds = 10.0;          ///< simulated time of the accuracy run (s)
  double restitution = 0.0;       ///< Bounce: the e every pair sees
  double slope_angle = 0.0;       ///< Incline: rad, the slope rises to +x
  double expected_accel = 0.0;    ///< Incline: analytic acceleration down the slope (m/s^2)
  double wall_x = 0.0;            ///< Bullet: x of the wall's centre (m)
};

/// Names the sweep runs, in report order; make_bench_scene also accepts the
/// Box2D v3 comparison stacks of stack_scenes.h.
std::vector<std::string> bench_scene_names();
/// Throws std::invalid_argument for an unknown name.
BenchScene make_bench_scene(const std::string& name);
/// The heavy-on-light stacks, one per mass ratio (10 ... 1e6).
std::vector<std::string> mass_ratio_scene_names();

std::string kind_name(SceneKind kind);
/// Name of the scene's main error column.
std::string error_name(SceneKind kind);

}  // namespace bench
}  // namespace collision2d
