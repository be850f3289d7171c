# Cyclone DDS (Debian cyclonedds-dev, C API) for remote/: the whiteboard's types as DDS topics.
# Targets link `ringlet_cyclonedds`, never CycloneDDS::ddsc directly.
#
# idlc (cyclonedds-tools) is a build-host program: the cross toolchain never looks for programs in
# the target's root (CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER), so the aarch64 build runs the host's
# idlc and compiles its C output for the robot (cyclonedds-dev:arm64 installs beside the host's).
find_package(CycloneDDS 0.10 CONFIG REQUIRED)
find_program(RINGLET_IDLC idlc REQUIRED DOC "Cyclone DDS IDL compiler (cyclonedds-tools)")
add_library(ringlet_cyclonedds INTERFACE)
target_link_libraries(ringlet_cyclonedds INTERFACE CycloneDDS::ddsc)
