// What every table of settings (WorldSettings, ResolveSettings) says about a
// field besides its type and default: its valid range, unit and a one-line doc.
// The tables themselves are X-macros (world_settings.h, resolve_settings.h), so
// a field is declared, validated, read, written and converted from one line.
#pragma once

#include <cstddef>
#include <limits>
#include <string>

#include "collision2d/solver_mode.h"
#include "collision2d/vec2.h"

namespace collision2d
{
/// Each physical effect is on when the scene needs it (Auto) unless forced.
enum class Toggle
{
  Auto,
  On,
  Off
};

/// How a field is stored; fixes its text form in files, messages and docs.
enum class SettingKind
{
  Vector,      ///< Vec2, both components finite
  Real,        ///< double
  Integer,     ///< int
  Count,       ///< std::size_t
  Flag,        ///< bool
  Toggle,      ///< auto | on | off
  SolverMode,  ///< iterative | exact
};

/// Valid values of a numeric field: finite, >= min (> min when min_exclusive)
/// and <= max. Choices (flags, toggles, modes) ignore it.
struct SettingRange
{
  double min = -std::numeric_limits<double>::infinity();
  double max = std::numeric_limits<double>::infinity();
  bool min_exclusive = false;
};

constexpr double kUnbounded = std::numeric_limits<double>::infinity();
constexpr SettingRange kAnyFinite{-kUnbounded, kUnbounded, false};
constexpr SettingRange kPositive{0.0, kUnbounded, true};
constexpr SettingRange kNonNegative{0.0, kUnbounded, false};
constexpr SettingRange kUnitInterval{0.0, 1.0, false};
constexpr SettingRange kAtLeastOne{1.0, kUnbounded, false};
/// Worker threads: more than a large machine has cores only costs.
constexpr SettingRange kWorkerCount{1.0, 256.0, false};

struct SettingInfo
{
  const char* name;
  SettingKind kind;
  SettingRange range;
  const char* unit;  ///< SI unit, "" when dimensionless
  const char* doc;   ///< one line
};

template <typename T>
constexpr SettingKind setting_kind();
template <>
constexpr SettingKind setting_kind<Vec2>() { return SettingKind::Vector; }
template <>
constexpr SettingKind setting_kind<double>() { return SettingKind::Real; }
template <>
constexpr SettingKind setting_kind<int>() { return SettingKind::Integer; }
template <>
constexpr SettingKind setting_kind<std::size_t>() { return SettingKind::Count; }
template <>
constexpr SettingKind setting_kind<bool>() { return SettingKind::Flag; }
template <>
constexpr SettingKind setting_kind<Toggle>() { return SettingKind::Toggle; }
template <>
constexpr SettingKind setting_kind<SolverMode>() { return SettingKind::SolverMode; }

/// True when `value` is finite and inside `range`.
bool in_range(const SettingRange& range, double value);
/// The rule as validation messages state it: "finite and > 0", "in [0, 1]", ">= 1".
std::string describe_range(const SettingRange& range, SettingKind kind);
/// The range in interval notation for tables and logs: "(0, inf)", "[0, 1]",
/// or the choices ("auto | on | off").
std::string range_text(const SettingRange& range, SettingKind kind);

/// Checks one field of a table against its range; throws
/// std::invalid_argument "<owner>.<field> must be <rule> (got <value>)".
class SettingCheck
{
public:
  explicit SettingCheck(const char* owner) : owner_(owner) {}

  void operator()(const SettingInfo& info, double value) const;
  void operator()(const SettingInfo& info, int value) const;
  void operator()(const SettingInfo& info, std::size_t value) const;
  void operator()(const SettingInfo& info, bool value) const;
  void operator()(const SettingInfo& info, Vec2 value) const;
  void operator()(const SettingInfo& info, Toggle value) const;
  void operator()(const SettingInfo& info, SolverMode value) const;

private:
  [[noreturn]] void reject(const SettingInfo& info, const std::string& rule, double value) const;

  const char* owner_;
};

/// The names files and docs use for the choices; from_text returns false for
/// any other text and leaves `out` alone.
const char* to_text(Toggle toggle);
const char* to_text(SolverMode mode);
const char* to_text(bool flag);
bool from_text(const std::string& text, Toggle& out);
bool from_text(const std::string& text, SolverMode& out);
bool from_text(const std::string& text, bool& out);
/// Shortest text (at most max_digits10) that reads back as the same double.
std::string number_text(double value);

/// A setting a file written by an earlier version may name: renamed (its value
/// is read as `replacement`) or retired (replacement empty: the value is
/// ignored). Either way the reader warns, naming the replacement.
struct FormerSetting
{
  const char* name;
  const char* replacement;  ///< the field it is read as, or "" when retired
  const char* note;         ///< why, for the warning
};

}  // namespace collision2d

// Expansions of a table line X(name, type, default, range, unit, doc): a
// member with its default, and a visit(info, member) call.
#define COLLISION2D_DECLARE_SETTING(name, type, default_value, range, unit, doc) type name = default_value;
#define COLLISION2D_VISIT_SETTING(name, type, default_value, range, unit, doc) \
  visit(SettingInfo{#name, setting_kind<type>(), range, unit, doc}, settings.name);

