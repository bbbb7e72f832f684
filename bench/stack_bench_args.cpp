// collision2d_stack_bench's command line (stack_bench_args.h).
#include "stack_bench_args.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <sstream>

#include <yaml-cpp/yaml.h>

#include "collision2d/scenes/scene_file.h"
#include "stack_scenes.h"

namespace collision2d
{
namespace bench
{
void stack_bench_usage(const std::string& problem)
{
  std::fprintf(stderr,
               "%s\nusage: collision2d_stack_bench [--seconds S[,S...]] [--reps N] [--timing-seconds T] "
               "[--scene NAME]... [--engine collision2d|box2d|chipmunk|box2d_v3]... [--csv FILE] "
               "[--soft-step on|off|both] [--stiff on|off] [--set NAME=VALUE]...\n",
               problem.c_str());
  std::exit(2);
}

namespace
{
std::vector<double> parse_seconds(const std::string& text)
{
  std::vector<double> values;
  std::stringstream in(text);
  std::string item;
  while (std::getline(in, item, ','))
  {
    const double s = std::atof(item.c_str());
    if (!(s > kStackSettleSeconds))
    {
      stack_bench_usage("--seconds: every value must exceed the " + std::to_string(kStackSettleSeconds) +
                        " s settling time");
    }
    values.push_back(s);
  }
  std::sort(values.begin(), values.end());
  return values;
}

std::pair<std::string, std::string> parse_set(const std::string& text)
{
  const std::size_t eq = text.find('=');
  if (eq == std::string::npos || eq == 0 || eq + 1 == text.size())
  {
    stack_bench_usage("--set takes NAME=VALUE, got '" + text + "'");
  }
  return {text.substr(0, eq), text.substr(eq + 1)};
}

EngineKind parse_engine(const std::string& name)
{
  EngineKind kind = EngineKind::Collision2d;
  if (!engine_from_name(name, kind))
  {
    stack_bench_usage("unknown engine '" + name + "'");
  }
  return kind;
}

}  // namespace

StackBenchArguments parse_stack_bench_arguments(int argc, char** argv)
{
  StackBenchArguments args;
  for (int i = 1; i < argc; ++i)
  {
    const std::string flag = argv[i];
    if (i + 1 >= argc)
    {
      stack_bench_usage("unknown or incomplete argument: " + flag);
    }
    const std::string value = argv[++i];
    if (flag == "--seconds")
    {
      args.seconds = parse_seconds(value);
    }
    else if (flag == "--reps")
    {
      args.repetitions = std::atoi(value.c_str());
    }
    else if (flag == "--timing-seconds")
    {
      args.timing_seconds = std::atof(value.c_str());
    }
    else if (flag == "--scene")
    {
      args.scenes.push_back(value);
    }
    else if (flag == "--engine")
    {
      args.engines.push_back(parse_engine(value));
    }
    else if (flag == "--csv")
    {
      args.csv = value;
    }
    else if (flag == "--soft-step")
    {
      if (value == "on")
      {
        args.pipelines = {Pipeline::Soft};
      }
      else if (value == "off")
      {
        args.pipelines = {Pipeline::Fx2d};
      }
      else if (value == "both")
      {
        args.pipelines = {Pipeline::Soft, Pipeline::Fx2d};
      }
      else
      {
        stack_bench_usage("--soft-step takes on, off or both");
      }
    }
    else if (flag == "--stiff" && (value == "on" || value == "off"))
    {
      args.stiff = value == "on";
    }
    else if (flag == "--set")
    {
      args.settings.push_back(parse_set(value));
    }
    else
    {
      stack_bench_usage("unknown argument: " + flag);
    }
  }
  if (args.repetitions < 1 || !(args.timing_seconds > 0.0) || args.seconds.empty())
  {
    stack_bench_usage("--reps, --timing-seconds and --seconds must be positive");
  }
  (void)with_set_fields(WorldSettings(), args);  // a bad --set stops here, before any run
  return args;
}

WorldSettings with_set_fields(WorldSettings settings, const StackBenchArguments& args)
{
  if (args.settings.empty())
  {
    return settings;
  }
  // Through the scene file reader, so the names, ranges and former names are
  // a scene file's: the settings written out, the fields set, read back.
  Scene holder;
  holder.settings = settings;
  try
  {
    YAML::Node file = YAML::Load(scenes::scene_to_yaml(holder));
    for (const auto& [name, text] : args.settings)
    {
      try
      {
        file["settings"][name] = YAML::Load(text);
      }
      catch (const YAML::Exception&)
      {
        stack_bench_usage("--set " + name + ": cannot read '" + text + "'");
      }
    }
    return scenes::parse_scene_yaml(YAML::Dump(file), "--set").settings;
  }
  catch (const std::exception& error)
  {
    stack_bench_usage(error.what());  // names the field, as for a scene file
  }
}

}  // namespace bench
}  // namespace collision2d
