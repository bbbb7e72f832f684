// Range checks and text forms shared by every table of settings.
#include "collision2d/setting_table.h"

#include <cmath>
#include <locale>
#include <sstream>
#include <stdexcept>

namespace collision2d
{
namespace
{
constexpr int kShortestTried = 15;  // digits always exact for decimal literals

std::string bound_text(double value)
{
  return std::isinf(value) ? (value > 0 ? "inf" : "-inf") : number_text(value);
}

}  // namespace

bool in_range(const SettingRange& range, double value)
{
  if (!std::isfinite(value))
  {
    return false;
  }
  const bool above_min = range.min_exclusive ? value > range.min : value >= range.min;
  return above_min && value <= range.max;
}

std::string describe_range(const SettingRange& range, SettingKind kind)
{
  const bool has_min = std::isfinite(range.min);
  const bool has_max = std::isfinite(range.max);
  if (has_min && has_max)
  {
    return "in [" + bound_text(range.min) + ", " + bound_text(range.max) + "]";
  }
  // Integers are finite by construction, so their rule is only the bound.
  const std::string finite = (kind == SettingKind::Integer || kind == SettingKind::Count) ? "" : "finite";
  if (!has_min)
  {
    return finite.empty() ? "any" : finite;
  }
  const std::string bound = std::string(range.min_exclusive ? "> " : ">= ") + bound_text(range.min);
  return finite.empty() ? bound : finite + " and " + bound;
}

std::string range_text(const SettingRange& range, SettingKind kind)
{
  switch (kind)
  {
    case SettingKind::Flag:
      return "true | false";
    case SettingKind::Toggle:
      return "auto | on | off";
    case SettingKind::SolverMode:
      return "iterative | exact";
    default:
      break;
  }
  const char open = range.min_exclusive || !std::isfinite(range.min) ? '(' : '[';
  const char close = std::isfinite(range.max) ? ']' : ')';
  return std::string(1, open) + bound_text(range.min) + ", " + bound_text(range.max) + close;
}

void SettingCheck::reject(const SettingInfo& info, const std::string& rule, double value) const
{
  std::ostringstream msg;
  msg << owner_ << "." << info.name << " must be " << rule << " (got " << value << ")";
  throw std::invalid_argument(msg.str());
}

void SettingCheck::operator()(const SettingInfo& info, double value) const
{
  if (!in_range(info.range, value))
  {
    reject(info, describe_range(info.range, info.kind), value);
  }
}

void SettingCheck::operator()(const SettingInfo& info, int value) const
{
  (*this)(info, static_cast<double>(value));
}

void SettingCheck::operator()(const SettingInfo& info, std::size_t value) const
{
  (*this)(info, static_cast<double>(value));
}

void SettingCheck::operator()(const SettingInfo&, bool) const {}

void SettingCheck::operator()(const SettingInfo& info, Vec2 value) const
{
  if (!is_finite(value))
  {
    reject(info, "finite", std::isfinite(value.x) ? value.y : value.x);
  }
}

void SettingCheck::operator()(const SettingInfo& info, Toggle value) const
{
  if (value != Toggle::Auto && value != Toggle::On && value != Toggle::Off)
  {
    reject(info, "Auto, On or Off", static_cast<double>(value));
  }
}

void SettingCheck::operator()(const SettingInfo& info, SolverMode value) const
{
  if (value != SolverMode::Iterative && value != SolverMode::Exact)
  {
    reject(info, "Iterative or Exact", static_cast<double>(value));
  }
}

const char* to_text(Toggle toggle)
{
  switch (toggle)
  {
    case Toggle::On:
      return "on";
    case Toggle::Off:
      return "off";
    case Toggle::Auto:
    default:
      return "auto";
  }
}

const char* to_text(SolverMode mode) { return mode == SolverMode::Exact ? "exact" : "iterative"; }

const char* to_text(bool flag) { return flag ? "true" : "false"; }

bool from_text(const std::string& text, Toggle& out)
{
  for (Toggle t : {Toggle::Auto, Toggle::On, Toggle::Off})
  {
    if (text == to_text(t))
    {
      out = t;
      return true;
    }
  }
  return false;
}

bool from_text(const std::string& text, SolverMode& out)
{
  for (SolverMode m : {SolverMode::Iterative, SolverMode::Exact})
  {
    if (text == to_text(m))
    {
      out = m;
      return true;
    }
  }
  return false;
}

bool from_text(const std::string& text, bool& out)
{
  if (text != "true" && text != "false")
  {
    return false;
  }
  out = text == "true";
  return true;
}

std::string number_text(double value)
{
  for (int digits = kShortestTried; digits <= std::numeric_limits<double>::max_digits10; ++digits)
  {
    std::ostringstream out;
    out.imbue(std::locale::classic());
    out.precision(digits);
    out << value;
    std::istringstream back(out.str());
    back.imbue(std::locale::classic());
    double parsed = 0.0;
    back >> parsed;
    if (parsed == value || digits == std::numeric_limits<double>::max_digits10)
    {
      return out.str();
    }
  }
  return "";  // unreachable: the loop returns at max_digits10
}

}  // namespace collision2d
