// Settings with every field of a table moved off its default (still valid),
// and field-by-field comparison from the same table, so a round trip that
// drops any field, present or added later, fails naming it.
#pragma once

#include <gtest/gtest.h>

#include "collision2d/resolve_settings.h"
#include "collision2d/world_settings.h"

namespace collision2d
{
namespace test
{
/// Moves each field to another valid value.
struct MoveOffDefault
{
  void operator()(const SettingInfo&, double& v) const { v = v == 0.0 ? 0.25 : 0.75 * v; }
  void operator()(const SettingInfo&, int& v) const { v += 3; }
  void operator()(const SettingInfo&, std::size_t& v) const { v += 7; }
  void operator()(const SettingInfo&, bool& v) const { v = !v; }
  void operator()(const SettingInfo&, Toggle& v) const { v = v == Toggle::Off ? Toggle::On : Toggle::Off; }
  void operator()(const SettingInfo&, SolverMode& v) const
  {
    v = v == SolverMode::Exact ? SolverMode::Iterative : SolverMode::Exact;
  }
  void operator()(const SettingInfo&, Vec2& v) const { v = Vec2{v.x + 0.25, 0.75 * v.y}; }
};

inline WorldSettings world_settings_off_default()
{
  WorldSettings s;
  visit_world_settings(s, MoveOffDefault{});
  return s;
}

inline ResolveSettings resolve_settings_off_default()
{
  ResolveSettings s;
  visit_resolve_settings(s, MoveOffDefault{});
  return s;
}

#define COLLISION2D_EXPECT_SAME_FIELD(name, type, default_value, range, unit, doc) \
  EXPECT_TRUE(a.name == b.name) << "setting " #name " differs";
#define COLLISION2D_EXPECT_OTHER_FIELD(name, type, default_value, range, unit, doc) \
  EXPECT_FALSE(a.name == b.name) << "setting " #name " is the same in both";

inline void expect_same_world_settings(const WorldSettings& a, const WorldSettings& b)
{
  COLLISION2D_WORLD_SETTINGS(COLLISION2D_EXPECT_SAME_FIELD)
}

/// Every field of `a` differs from `b`'s (a test's input really is off default).
inline void expect_every_world_setting_differs(const WorldSettings& a, const WorldSettings& b)
{
  COLLISION2D_WORLD_SETTINGS(COLLISION2D_EXPECT_OTHER_FIELD)
}

inline void expect_same_resolve_settings(const ResolveSettings& a, const ResolveSettings& b)
{
  COLLISION2D_RESOLVE_SETTINGS(COLLISION2D_EXPECT_SAME_FIELD)
}

inline void expect_every_resolve_setting_differs(const ResolveSettings& a, const ResolveSettings& b)
{
  COLLISION2D_RESOLVE_SETTINGS(COLLISION2D_EXPECT_OTHER_FIELD)
}

}  // namespace test
}  // namespace collision2d
