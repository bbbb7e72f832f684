// libFuzzer target: YAML scene text -> parse_scene_yaml -> make_world -> a
// few frames. Rejections must be std::runtime_error messages that start with
// the source name (located errors); what parses must build a world and step
// without sanitizer reports and stay finite. Only a scene outside the ranges
// of fuzz_support.h may overflow, and the step must then throw
// std::overflow_error rather than return a non-finite state.
//
// Bounded work per input: `generate:` entries can ask for millions of bodies
// (pyramid base 1e5 is 5e9 boxes) and settings for millions of substeps, and
// the parser accepts both, so inputs whose generators would exceed
// kMaxBodies are skipped before parsing and substeps/iterations are capped.
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>

#include "collision2d/scene.h"
#include "collision2d/scenes/scene_file.h"
#include "fuzz_support.h"

using namespace collision2d;

namespace
{
constexpr double kMaxBodies = 2000.0;
constexpr int kMaxSubsteps = 8;
constexpr int kMaxIterations = 8;
constexpr int kFrames = 3;
const std::string kSource = "fuzz.yaml";

/// Bodies one generator entry asks for (defaults as in scene_parts.h), or
/// kMaxBodies + 1 when its count cannot be read.
double generated_bodies(const YAML::Node& entry)
{
  if (!entry.IsMap() || entry.size() != 1)
  {
    return 0.0;  // the parser rejects it
  }
  const auto item = *entry.begin();
  const std::string kind = item.first.IsScalar() ? item.first.Scalar() : "";
  const YAML::Node fields = item.second;
  auto field = [&](const char* key, double fallback) {
    if (!fields.IsMap() || !fields[key])
    {
      return fallback;
    }
    try
    {
      return std::abs(fields[key].as<double>());
    }
    catch (const YAML::Exception&)
    {
      return fallback;  // not a number: the parser rejects it
    }
  };
  if (kind == "pyramid")
  {
    const double base = field("base", 20.0);
    return base * (base + 1.0) / 2.0;
  }
  if (kind == "column")
    return field("count", 20.0);
  if (kind == "cradle" || kind == "disk_row")
    return field("count", 5.0);
  if (kind == "gas")
    return field("count", 1000.0);
  return 4.0;  // ground, container, incline: at most four bodies
}

bool bounded(const std::string& text)
{
  try
  {
    const YAML::Node root = YAML::Load(text);
    if (!root.IsMap() || !root["generate"] || !root["generate"].IsSequence())
    {
      return true;
    }
    double total = 0.0;
    for (const YAML::Node& entry : root["generate"])
    {
      total += generated_bodies(entry);
    }
    return total <= kMaxBodies;
  }
  catch (const YAML::Exception&)
  {
    return true;  // the parser must reject it with a located error
  }
}

bool in_range(const Scene& scene)
{
  const WorldSettings& s = scene.settings;
  if (!(s.dt <= fuzz::kMaxDt && length(s.gravity) <= fuzz::kMaxGravity))
  {
    return false;
  }
  for (const SceneBody& b : scene.bodies)
  {
    if (!fuzz::in_range(b.body))
    {
      return false;
    }
  }
  return true;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  const std::string text(reinterpret_cast<const char*>(data), size);
  if (!bounded(text))
  {
    return 0;
  }
  Scene scene;
  try
  {
    scene = scenes::parse_scene_yaml(text, kSource);
  }
  catch (const std::runtime_error& error)
  {
    fuzz::require(std::string(error.what()).rfind(kSource, 0) == 0, "YAML rejection does not name its source");
    return 0;
  }
  scene.settings.substeps = std::min(scene.settings.substeps, kMaxSubsteps);
  scene.settings.velocity_iterations = std::min(scene.settings.velocity_iterations, kMaxIterations);
  World world = make_world(scene);
  try
  {
    world.step(kFrames);
  }
  catch (const std::overflow_error&)
  {
    fuzz::require(!in_range(scene), "world step of an in-range scene overflowed");
    return 0;
  }
  // A step that returns has a finite state; overflow must throw instead.
  for (BodyId id : world.body_ids())
  {
    fuzz::require(fuzz::finite_state(world.body(id)), "world step returned a non-finite body");
  }
  return 0;
}
