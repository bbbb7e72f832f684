// docs/ros_interface.md's settings section is the tables' own rendering: this
// test renders it and compares. COLLISION2D_UPDATE_DOCS=1 rewrites the section.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "collision2d/resolve_settings.h"
#include "collision2d/world_settings.h"

namespace collision2d
{
namespace
{
const char* const kBegin = "<!-- settings-table:begin";
const char* const kEnd = "<!-- settings-table:end -->";

std::filesystem::path docs_path()
{
  // test/unit/ -> repository root, wherever the binary runs.
  return std::filesystem::path(__FILE__).parent_path().parent_path().parent_path() / "docs" / "ros_interface.md";
}

const char* type_name(SettingKind kind)
{
  switch (kind)
  {
    case SettingKind::Vector:
      return "vector";
    case SettingKind::Real:
      return "real";
    case SettingKind::Integer:
      return "integer";
    case SettingKind::Count:
      return "count";
    case SettingKind::Flag:
      return "bool";
    case SettingKind::Toggle:
      return "toggle";
    case SettingKind::SolverMode:
      return "solver mode";
  }
  return "";
}

/// One table row per field: names, type, default, valid values, unit, doc.
class RowWriter
{
public:
  RowWriter(std::ostream& out, const std::string& message, const std::string& prefix, bool in_files)
    : out_(out), message_(message), prefix_(prefix), in_files_(in_files)
  {
  }

  void operator()(const SettingInfo& info, double v) { row(info, number_text(v)); }
  void operator()(const SettingInfo& info, int v) { row(info, std::to_string(v)); }
  void operator()(const SettingInfo& info, std::size_t v) { row(info, std::to_string(v)); }
  void operator()(const SettingInfo& info, bool v) { row(info, to_text(v)); }
  void operator()(const SettingInfo& info, Toggle v) { row(info, to_text(v)); }
  void operator()(const SettingInfo& info, SolverMode v) { row(info, to_text(v)); }
  void operator()(const SettingInfo& info, Vec2 v)
  {
    row(info, "[" + number_text(v.x) + ", " + number_text(v.y) + "]", "_x`, `" + prefix_ + info.name + "_y");
  }

private:
  void row(const SettingInfo& info, const std::string& value, const std::string& cfg_suffix = "")
  {
    std::string valid = range_text(info.range, info.kind);
    for (std::size_t at = valid.find('|'); at != std::string::npos; at = valid.find('|', at + 2))
    {
      valid.insert(at, "\\");  // a bar inside a cell would end it
    }
    out_ << "| `" << info.name << "` | `" << message_ << "` | " << (in_files_ ? "yes" : "no") << " | `" << prefix_
         << info.name << cfg_suffix << "` | " << type_name(info.kind) << " | `" << value << "` | " << valid << " | " << info.unit << " | " << info.doc << " |\n";
  }

  std::ostream& out_;
  std::string message_;
  std::string prefix_;
  bool in_files_;
};

std::string rendered_section()
{
  std::ostringstream out;
  out << kBegin << " (rendered from include/collision2d/world_settings.h and resolve_settings.h by "
      << "test/unit/test_settings_docs.cpp; COLLISION2D_UPDATE_DOCS=1 rewrites it) -->\n";
  out << "| field | message | scene files | dynamic_reconfigure | type | default | valid | unit | meaning |\n";
  out << "|---|---|---|---|---|---|---|---|---|\n";
  const WorldSettings world;
  visit_world_settings(world, RowWriter(out, "WorldConfig", "world_", true));
  const ResolveSettings resolve;
  visit_resolve_settings(resolve, RowWriter(out, "SolverSettings", "solver_", false));
  out << "\nFormer names still read from scene and snapshot files (with a WARN naming the replacement, or "
      << "saying the setting is retired and ignored):";
  out << (former_world_settings().empty() ? " none yet.\n" : "\n\n");
  for (const FormerSetting& former : former_world_settings())
  {
    out << "- `" << former.name << "`: "
        << (former.replacement[0] == '\0' ? std::string("retired") : "now `" + std::string(former.replacement) + "`")
        << (former.note[0] == '\0' ? "" : " (" + std::string(former.note) + ")") << "\n";
  }
  out << kEnd;
  return out.str();
}

TEST(SettingsDocs, TheDocsTableIsTheTables)
{
  std::ifstream in(docs_path());
  ASSERT_TRUE(in) << docs_path();
  std::stringstream buffer;
  buffer << in.rdbuf();
  std::string text = buffer.str();
  const std::size_t begin = text.find(kBegin);
  const std::size_t end = text.find(kEnd);
  ASSERT_NE(begin, std::string::npos) << "no settings table in " << docs_path();
  ASSERT_NE(end, std::string::npos);
  const std::string expected = rendered_section();
  const std::string found = text.substr(begin, end + std::string(kEnd).size() - begin);
  const char* update = std::getenv("COLLISION2D_UPDATE_DOCS");
  if (found != expected && update != nullptr && std::string(update) == "1")
  {
    text.replace(begin, found.size(), expected);
    std::ofstream(docs_path()) << text;
    return;
  }
  EXPECT_EQ(found, expected) << "run this test with COLLISION2D_UPDATE_DOCS=1 to rewrite the section";
}

}  // namespace
}  // namespace collision2d
