# The Debian package: `cpack -G DEB` in a build tree (or `cmake --build <tree> --target package`)
# makes ringlet_<version>_<arch>.deb of everything `cmake --install` installs. README.md, "Deployment".
#
# The architecture is the target's, not the build host's: the aarch64 preset's cross tree makes an
# arm64 package on an amd64 machine. The package's paths are the tree's CMAKE_INSTALL_PREFIX (the
# systemd units name them): the aarch64 preset configures /usr, the robot's layout; a host tree
# keeps CMake's /usr/local, which systemd and sysusers also search.

# Debian's name for the target's architecture.
string(TOLOWER "${CMAKE_SYSTEM_PROCESSOR}" _cpu)
if(_cpu MATCHES "^(aarch64|arm64)$")
  set(RINGLET_DEB_ARCH arm64)
elseif(_cpu MATCHES "^(x86_64|amd64)$")
  set(RINGLET_DEB_ARCH amd64)
elseif(_cpu MATCHES "^armv7")
  set(RINGLET_DEB_ARCH armhf)
elseif(_cpu MATCHES "^riscv64$")
  set(RINGLET_DEB_ARCH riscv64)
else()
  set(RINGLET_DEB_ARCH "")
  message(STATUS "RingletPackage: no Debian architecture known for '${CMAKE_SYSTEM_PROCESSOR}': "
                 "set CPACK_DEBIAN_PACKAGE_ARCHITECTURE before packaging")
endif()

# `cmake --install` and cpack install what is built, and do not build the whole tree (tests,
# benchmarks) first: build the programs, then package them (README.md, "Deployment").
set(CMAKE_SKIP_INSTALL_ALL_DEPENDENCY ON)

set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME ringlet)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "Ringlet real-time robot controller (firmware, CAN board tools, monitor)")
set(CPACK_PACKAGE_DESCRIPTION
    "The ringlet firmware (a cyclic executive running LLFSMs on a whiteboard), its robot configuration in /etc/ringlet, systemd units that bring up the CAN bus and run the controller with real-time rights, the board's DBC file, ringlet-board-sim (the software board), ringlet-monitor, ringlet-jitter and ringlet-can-spec; the vision tools where the build has OpenCV.")
set(CPACK_PACKAGE_CONTACT "Seed 9e097c6f maintainers <maintainers@users.noreply.h-seed-9e097c6f.example>")
set(CPACK_DEBIAN_PACKAGE_MAINTAINER "${CPACK_PACKAGE_CONTACT}")
set(CPACK_DEBIAN_PACKAGE_SECTION misc)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)   # ringlet_<version>_<arch>.deb
if(RINGLET_DEB_ARCH)
  set(CPACK_DEBIAN_PACKAGE_ARCHITECTURE ${RINGLET_DEB_ARCH})
endif()

# Files go where `cmake --install` puts them, absolute ones (/etc/ringlet) included: CPack installs
# with DESTDIR into its staging folder, with this tree's prefix.
set(CPACK_SET_DESTDIR ON)
set(CPACK_PACKAGING_INSTALL_PREFIX ${CMAKE_INSTALL_PREFIX})
set(CPACK_INSTALL_PREFIX ${CMAKE_INSTALL_PREFIX})
# Binaries without their debugging sections on the robot (the cross toolchain's strip for arm64).
set(CPACK_STRIP_FILES ON)

# Depends: the shared libraries, found by dpkg-shlibdeps from the binaries themselves. It reads
# foreign ELF files too, so it works for the cross tree as long as the arm64 -dev packages of the
# build (libtomlplusplus-dev:arm64, cyclonedds-dev:arm64, ...) are installed, which the build
# needs anyway. iproute2: ringlet-can@.service runs ip(8). can-utils (candump, cansend) is what
# one watches the bus with on the bench.
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_DEPENDS "iproute2")
# The cross build's OpenCV comes from the arm64 sysroot (tools/arm64_sysroot.sh), whose files no
# installed package owns: dpkg-shlibdeps finds them there (-l) but cannot name their packages, so
# they are named here, the modules the camera links. On the robot apt installs Debian's own.
if(RINGLET_OPENCV_LIBDIRS)
  set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS_PRIVATE_DIRS ${RINGLET_OPENCV_LIBDIRS})
  string(APPEND CPACK_DEBIAN_PACKAGE_DEPENDS
         ", libopencv-core406, libopencv-imgproc406, libopencv-imgcodecs406, libopencv-videoio406")
endif()
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "can-utils, systemd")

# Maintainer scripts (create the user, reload systemd; never start anything) and the conffile.
set(_deb ${PROJECT_SOURCE_DIR}/firmware/deploy/debian)
file(WRITE ${PROJECT_BINARY_DIR}/deb/conffiles "${CMAKE_INSTALL_FULL_SYSCONFDIR}/ringlet/robot.toml\n")
set(CPACK_DEBIAN_PACKAGE_CONTROL_EXTRA ${_deb}/postinst ${_deb}/prerm ${_deb}/postrm ${PROJECT_BINARY_DIR}/deb/conffiles)
set(CPACK_DEBIAN_PACKAGE_CONTROL_STRICT_PERMISSION ON)

include(CPack)
