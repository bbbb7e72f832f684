// collision2d_stack_bench's command line (stack_bench_args.h).
#include "stack_bench_args.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <stdexcept>

#include "collision2d/setting_table.h"
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

/// Sets the field named `name` from `text`, as a scene file would; `found`
/// says whether a field had that name, `read` whether the text was its kind.
class FieldSetter
{
public:
  FieldSetter(const std::string& name, const std::string& text) : name_(name), text_(text) {}

  void operator()(const SettingInfo& info, double& value)
  {
    set(info, value, [&](std::size_t* used) { return std::stod(text_, used); });
  }
  void operator()(const SettingInfo& info, int& value)
  {
    set(info, value, [&](std::size_t* used) { return std::stoi(text_, used); });
  }
  void operator()(const SettingInfo& info, std::size_t& value)
  {
    set(info, value, [&](std::size_t* used) { return static_cast<std::size_t>(std::stoull(text_, used)); });
  }
  template <class Choice>
  void operator()(const SettingInfo& info, Choice& value)
  {
    if (info.name == name_)
    {
      found = true;
      read = from_text(text_, value);
    }
  }
  void operator()(const SettingInfo& info, Vec2&) { found = found || info.name == name_; }

  bool found = false;
  bool read = false;

private:
  template <class T, class Parse>
  void set(const SettingInfo& info, T& value, Parse parse)
  {
    if (info.name != name_)
    {
      return;
    }
    found = true;
    try
    {
      std::size_t used = 0;
      value = parse(&used);
      read = used == text_.size();  // the whole text is the number
    }
    catch (const std::exception&)
    {
      read = false;
    }
  }

  const std::string& name_;
  const std::string& text_;
};

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
  for (const auto& [name, text] : args.settings)
  {
    FieldSetter setter(name, text);
    visit_world_settings(settings, setter);
    if (!setter.found || !setter.read)
    {
      stack_bench_usage(setter.found ? "--set " + name + ": cannot read '" + text + "'"
                                     : "--set: WorldSettings has no field '" + name + "'");
    }
  }
  try
  {
    validate_world_settings(settings);
  }
  catch (const std::invalid_argument& error)
  {
    stack_bench_usage(std::string("--set: ") + error.what());
  }
  return settings;
}

}  // namespace bench
}  // namespace collision2d
