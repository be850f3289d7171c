# Cross toolchain: Debian 12 host -> aarch64 (arm64) Linux robot computer.
#
# Uses Debian's multiarch layout, no separate sysroot:
#   compilers      g++-aarch64-linux-gnu            (/usr/bin/aarch64-linux-gnu-g++)
#   C/C++ runtime  /usr/aarch64-linux-gnu           (libc6-arm64-cross, used at link time)
#   libraries      /usr/lib/aarch64-linux-gnu       (libtomlplusplus-dev:arm64, libgtest-dev:arm64, ...)
#   header-only    /usr/share/cmake, /usr/share/eigen3/cmake, /usr/share/nanoflann/cmake,
#                  /usr/include (Eigen3, CLI11, nlohmann_json, nanoflann: arch-independent
#                  packages, found from the host tree)
#
# Binaries run under user-mode qemu: `qemu-aarch64 ./prog`, never with -L (or QEMU_LD_PREFIX):
# the arm64 dynamic loader and libraries come from the multiarch libc6:arm64 in /lib and
# /usr/lib/aarch64-linux-gnu; adding -L /usr/aarch64-linux-gnu mixes two glibc builds in one
# process and the first pthread_create hangs. No binfmt registration is assumed: CTest and
# gtest_discover_tests call the emulator explicitly through CMAKE_CROSSCOMPILING_EMULATOR.

set(CMAKE_SYSTEM_NAME Linux)
set(CMAKE_SYSTEM_PROCESSOR aarch64)

set(CMAKE_C_COMPILER aarch64-linux-gnu-gcc)
set(CMAKE_CXX_COMPILER aarch64-linux-gnu-g++)
set(CMAKE_LIBRARY_ARCHITECTURE aarch64-linux-gnu)

# The cross runtime first, then the host root for the multiarch libraries
# (/usr/lib/aarch64-linux-gnu/...) and the arch-independent CMake package configs.
set(CMAKE_FIND_ROOT_PATH /usr/aarch64-linux-gnu /)

# Programs (code generators, qemu, bash) are the host's; libraries, headers and packages only
# from the roots above. With CMAKE_LIBRARY_ARCHITECTURE set, the package search looks in
# <prefix>/lib/aarch64-linux-gnu/cmake (tomlplusplus, GTest arm64 configs) and <prefix>/share
# (Eigen3, CLI11, nlohmann_json), never in /usr/lib/x86_64-linux-gnu.
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)

# pkg-config (if any find module falls back to it) must see the arm64 .pc files only.
set(ENV{PKG_CONFIG_LIBDIR} "/usr/lib/aarch64-linux-gnu/pkgconfig:/usr/share/pkgconfig")
set(ENV{PKG_CONFIG_SYSROOT_DIR} "")

# Run target binaries (ctest, gtest_discover_tests) through user-mode qemu, explicitly.
find_program(RINGLET_QEMU_AARCH64 NAMES qemu-aarch64 qemu-aarch64-static)
if(RINGLET_QEMU_AARCH64)
  set(CMAKE_CROSSCOMPILING_EMULATOR "${RINGLET_QEMU_AARCH64}")
else()
  # Not installed yet (configure still works); ctest will say qemu-aarch64 is missing.
  set(CMAKE_CROSSCOMPILING_EMULATOR qemu-aarch64)
endif()
