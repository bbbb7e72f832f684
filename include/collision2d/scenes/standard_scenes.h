// The standard scenes: the one place that builds them, shared by the tests,
// the benchmarks, the ROS node and the rviz demo. SI units, y up, gravity
// -9.81 m/s^2 unless a scene says otherwise; ground and walls are static.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "collision2d/scene.h"

namespace collision2d
{
namespace scenes
{
/// One 1 m box resting on the ground.
Scene resting_box();
/// `base` boxes of 1 m in the bottom row, one fewer per row above.
Scene pyramid(int base = 20);
/// A vertical stack of n boxes of 1 m.
Scene column(int n = 20);
/// n touching equal disks (e = 1, mu = 0, no gravity); the first moves at 1 m/s.
Scene newtons_cradle(int n = 5);
/// A 1 m box resting on a static slab tilted by angle_rad.
Scene incline(double angle_rad = 0.4, double mu_s = 0.5, double mu_k = 0.3);
/// n disks dropped from increasing heights onto the ground, restitution e.
Scene bouncing_disks(int n = 5, double e = 0.8);
/// n disks in a static box: e = 1, mu = 0, no gravity, random velocities.
Scene elastic_gas(int n = 1000, std::uint64_t seed = 7);
/// A small disk at `speed` (m/s) toward a 5 cm static wall, no gravity.
Scene bullet_wall(double speed = 500.0);
/// A box `ratio` times heavier resting on a 1 kg box on the ground.
Scene heavy_on_light(double ratio = 100.0);
/// The lively rviz scene: a pyramid, bouncing disks and a spinning box
/// thrown at the pyramid.
Scene demo();

/// Names accepted by make_standard_scene, in a stable order.
std::vector<std::string> standard_scene_names();
/// The named scene with its default parameters; throws std::invalid_argument
/// ("unknown scene 'x'") for any other name.
Scene make_standard_scene(const std::string& name);

}  // namespace scenes
}  // namespace collision2d
