// The benchmark scene catalogue (see bench_scenes.h).
#include "bench_scenes.h"

#include <cmath>
#include <stdexcept>

#include "collision2d/scenes/standard_scenes.h"
#include "stack_scenes.h"

namespace collision2d
{
namespace bench
{
namespace
{
constexpr double kGravity = 9.81;             // m/s^2
constexpr double kStackSeconds = 10.0;        // long enough for a slow creep to show (s)
constexpr double kPyramidSeconds = 5.0;       // s: 210 boxes cost; the stand runs go to 60 s
constexpr double kGasSeconds = 10.0;          // s: the energy target's span, many crossings at up to 2 m/s
constexpr double kCradleSeconds = 5.0;        // several passes of the pulse (s)
constexpr double kBounceSeconds = 3.0;        // every disk bounces at least once (s)
constexpr double kInclineSeconds = 2.0;       // the sliding box stays on the slab (s)
constexpr double kBulletSeconds = 0.5;        // the bullet reaches the wall after 10 ms (s)
constexpr double kBounceRestitution = 0.8;
constexpr double kBulletSpeed = 500.0;        // m/s
constexpr double kFastBulletSpeed = 1e4;      // m/s: the fastest body the supported ranges promise
constexpr double kBulletWallX = 5.0;          // m, as scenes::bullet_wall builds it
constexpr double kRestingAngle = 0.4;         // rad: tan = 0.42 < mu_s = 0.5, the box holds
constexpr double kRestingMuS = 0.5;
constexpr double kRestingMuK = 0.3;
constexpr double kSlidingAngle = 0.6;         // rad: tan = 0.68 > mu = 0.3, the box slides
constexpr double kSlidingMu = 0.3;            // mu_s = mu_k: the peers have one coefficient
const char* const kRatioNames[] = {"1e1", "1e2", "1e3", "1e4", "1e5", "1e6"};

double incline_acceleration(double angle, double mu_s, double mu_k)
{
  return std::tan(angle) <= mu_s ? 0.0 : kGravity * (std::sin(angle) - mu_k * std::cos(angle));
}

BenchScene incline_scene(const std::string& name, double angle, double mu_s, double mu_k)
{
  BenchScene s{name, scenes::incline(angle, mu_s, mu_k), SceneKind::Incline, kInclineSeconds};
  s.slope_angle = angle;
  s.expected_accel = incline_acceleration(angle, mu_s, mu_k);
  return s;
}

}  // namespace

std::vector<std::string> mass_ratio_scene_names()
{
  std::vector<std::string> names;
  for (const char* ratio : kRatioNames)
  {
    names.push_back(std::string("heavy_on_light_") + ratio);
  }
  return names;
}

std::vector<std::string> bench_scene_names()
{
  std::vector<std::string> names = {"pyramid", "column", "elastic_gas", "newtons_cradle", "bouncing_disks",
                                    "incline", "incline_slide", "bullet_wall", "bullet_wall_1e4"};
  for (const std::string& n : mass_ratio_scene_names())
  {
    names.push_back(n);
  }
  return names;
}

BenchScene make_bench_scene(const std::string& name)
{
  if (name == "pyramid")
  {
    return BenchScene{name, scenes::pyramid(20), SceneKind::Resting, kPyramidSeconds};
  }
  if (name == "column")
  {
    return BenchScene{name, scenes::column(20), SceneKind::Resting, kStackSeconds};
  }
  if (name == "elastic_gas")
  {
    return BenchScene{name, scenes::elastic_gas(1000), SceneKind::Conservative, kGasSeconds};
  }
  if (name == "newtons_cradle")
  {
    return BenchScene{name, scenes::newtons_cradle(5), SceneKind::Conservative, kCradleSeconds};
  }
  if (name == "bouncing_disks")
  {
    BenchScene s{name, scenes::bouncing_disks(5, kBounceRestitution), SceneKind::Bounce, kBounceSeconds};
    s.restitution = kBounceRestitution;
    return s;
  }
  if (name == "incline")
  {
    return incline_scene(name, kRestingAngle, kRestingMuS, kRestingMuK);
  }
  if (name == "incline_slide")
  {
    return incline_scene(name, kSlidingAngle, kSlidingMu, kSlidingMu);
  }
  if (name == "bullet_wall" || name == "bullet_wall_1e4")
  {
    const double speed = name == "bullet_wall" ? kBulletSpeed : kFastBulletSpeed;
    BenchScene s{name, scenes::bullet_wall(speed), SceneKind::Bullet, kBulletSeconds};
    s.scene.name = name;
    s.wall_x = kBulletWallX;
    return s;
  }
  if (is_stack_scene(name))
  {
    return make_stack_scene(name);
  }
  const std::string prefix = "heavy_on_light_";
  if (name.compare(0, prefix.size(), prefix) == 0)
  {
    const double ratio = std::stod(name.substr(prefix.size()));
    BenchScene s{name, scenes::heavy_on_light(ratio), SceneKind::Resting, kStackSeconds};
    s.scene.name = name;
    return s;
  }
  throw std::invalid_argument("unknown bench scene '" + name + "'");
}

std::string kind_name(SceneKind kind)
{
  switch (kind)
  {
    case SceneKind::Resting:
      return "resting";
    case SceneKind::Conservative:
      return "conservative";
    case SceneKind::Bounce:
      return "bounce";
    case SceneKind::Incline:
      return "incline";
    case SceneKind::Bullet:
      return "bullet";
  }
  return "?";
}

std::string error_name(SceneKind kind)
{
  switch (kind)
  {
    case SceneKind::Resting:
      return "drift_m";
    case SceneKind::Conservative:
      return "energy_error";
    case SceneKind::Bounce:
      return "bounce_error";
    case SceneKind::Incline:
      return "incline_accel_error";
    case SceneKind::Bullet:
      return "tunnelled";
  }
  return "?";
}

}  // namespace bench
}  // namespace collision2d
