// collision2d_stack_bench's command line (stack_bench_args.h).
#include "stack_bench_args.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <sstream>

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
               "[--soft-step on|off|both] [--stiff on|off]\n",
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
    else
    {
      stack_bench_usage("unknown argument: " + flag);
    }
  }
  if (args.repetitions < 1 || !(args.timing_seconds > 0.0) || args.seconds.empty())
  {
    stack_bench_usage("--reps, --timing-seconds and --seconds must be positive");
  }
  return args;
}

}  // namespace bench
}  // namespace collision2d
