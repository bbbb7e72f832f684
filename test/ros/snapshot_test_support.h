// Shared by the snapshot tests of the ROS face (test_world_snapshot.cpp and
// test_world_snapshot_service.cpp, one test binary): a temporary folder of
// their own, and whole files read and written.
#pragma once

#include <stdlib.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <system_error>

namespace collision2d
{
namespace ros_interface
{
namespace snapshot_test
{
namespace fs = std::filesystem;

/// Tests run in the package folder (WORKING_DIRECTORY in CMakeLists.txt).
inline const char* const kScenesDir = "config/scenes";

/// A folder of its own under the system temp folder, removed afterwards.
class TempFolder
{
public:
  TempFolder()
  {
    std::string name = (fs::temp_directory_path() / "collision2d_snapshot_XXXXXX").string();
    if (::mkdtemp(name.data()) == nullptr)
    {
      throw std::runtime_error("mkdtemp failed");
    }
    path_ = name;
  }
  ~TempFolder()
  {
    std::error_code ignored;
    fs::remove_all(path_, ignored);
  }
  std::string file(const std::string& name) const { return (path_ / name).string(); }
  const fs::path& path() const { return path_; }

private:
  fs::path path_;
};

inline std::string read_text(const std::string& path)
{
  std::ifstream in(path);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

inline void write_text(const std::string& path, const std::string& text)
{
  std::ofstream(path) << text;
}

}  // namespace snapshot_test
}  // namespace ros_interface
}  // namespace collision2d
