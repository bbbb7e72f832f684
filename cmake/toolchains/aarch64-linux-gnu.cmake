# Cross-compiling for 64-bit Arm Linux with Debian's cross toolchain
# (g++-aarch64-linux-gnu); see docs/aarch64.md. Eigen is header-only and is
# taken from the build machine; libraries (yaml-cpp, gtest) must be aarch64
# builds, found under the cross sysroot, the multiarch folders or an extra root.
set(CMAKE_SYSTEM_NAME Linux)
set(CMAKE_SYSTEM_PROCESSOR aarch64)
set(CMAKE_C_COMPILER aarch64-linux-gnu-gcc)
set(CMAKE_CXX_COMPILER aarch64-linux-gnu-g++)

# An extra root holding aarch64 packages unpacked without installing them
# (e.g. `dpkg -x libyaml-cpp-dev_*_arm64.deb /tmp/arm64root`): the cache
# variable, else the environment variable of the same name.
set(COLLISION2D_AARCH64_EXTRA_ROOT "$ENV{COLLISION2D_AARCH64_EXTRA_ROOT}" CACHE PATH
  "Extra root of unpacked aarch64 packages (yaml-cpp, gtest)")
set(CMAKE_FIND_ROOT_PATH /usr/aarch64-linux-gnu ${COLLISION2D_AARCH64_EXTRA_ROOT})
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE BOTH)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE BOTH)

# ctest and gtest_discover_tests run the test programs through qemu-user; the
# extra root's shared libraries (libyaml-cpp) are put on its library path.
set(_collision2d_emulator qemu-aarch64 -L /usr/aarch64-linux-gnu)
if(COLLISION2D_AARCH64_EXTRA_ROOT)
  list(APPEND _collision2d_emulator
    -E LD_LIBRARY_PATH=${COLLISION2D_AARCH64_EXTRA_ROOT}/usr/lib/aarch64-linux-gnu)
endif()
set(CMAKE_CROSSCOMPILING_EMULATOR ${_collision2d_emulator})
