# OpenCV, for the camera backend and the desktop tools (image files, Canny + HoughLinesP as a
# baseline); never for the algorithms, which run on the robot inside their budgets.
#
# The host build requires it (libopencv-dev). The aarch64 cross build takes it from the arm64
# sysroot that tools/arm64_sysroot.sh makes of Debian's arm64 packages (they cannot be installed
# next to the amd64 ones): RINGLET_ARM64_SYSROOT, set by the aarch64 preset. Without it the cross
# build has no OpenCV and no camera backend. RINGLET_HAVE_OPENCV says which.
#
# Who links OpenCV: the `ringlet` binary (through firmware/camera_opencv), the camera backend's own
# tests and the desktop tools. Nothing else: under qemu-aarch64 loading OpenCV's ~240 libraries
# costs ~2 s per process start, and every gtest case is a process.
set(RINGLET_ARM64_SYSROOT "" CACHE PATH
    "arm64 sysroot with OpenCV made by tools/arm64_sysroot.sh (cross builds only; the aarch64 preset sets it)")

if(NOT CMAKE_CROSSCOMPILING)
  find_package(OpenCV REQUIRED COMPONENTS core imgproc imgcodecs videoio)
  set(RINGLET_HAVE_OPENCV ${OpenCV_FOUND})
  add_library(ringlet_opencv INTERFACE)
  target_link_libraries(ringlet_opencv INTERFACE ${OpenCV_LIBS})
  target_include_directories(ringlet_opencv SYSTEM INTERFACE ${OpenCV_INCLUDE_DIRS})
elseif(RINGLET_ARM64_SYSROOT AND EXISTS "${RINGLET_ARM64_SYSROOT}/.ringlet-libdirs")
  # The sysroot has only the four modules the camera needs, not libopencv-dev's OpenCVConfig.cmake
  # (whose module list names every module and fails on the missing ones): imported targets here.
  # The script wrote the folders that OpenCV's libraries, transitively, load from.
  file(STRINGS "${RINGLET_ARM64_SYSROOT}/.ringlet-libdirs" _ringlet_sysroot_libdirs)
  set(_lib "${RINGLET_ARM64_SYSROOT}/usr/lib/aarch64-linux-gnu")
  add_library(ringlet_opencv INTERFACE)
  foreach(m core imgproc imgcodecs videoio)
    if(NOT EXISTS "${_lib}/libopencv_${m}.so")
      message(FATAL_ERROR "RINGLET_ARM64_SYSROOT=${RINGLET_ARM64_SYSROOT} has no ${_lib}/libopencv_${m}.so: "
                          "run tools/arm64_sysroot.sh --sysroot ${RINGLET_ARM64_SYSROOT}")
    endif()
    add_library(opencv_${m} SHARED IMPORTED)
    set_target_properties(opencv_${m} PROPERTIES IMPORTED_LOCATION "${_lib}/libopencv_${m}.so")
    target_link_libraries(ringlet_opencv INTERFACE opencv_${m})
  endforeach()
  target_include_directories(ringlet_opencv SYSTEM INTERFACE "${RINGLET_ARM64_SYSROOT}/usr/include/opencv4")
  set(RINGLET_OPENCV_LIBDIRS ${_ringlet_sysroot_libdirs})
  set(RINGLET_HAVE_OPENCV ON)
  message(STATUS "OpenCV for aarch64 from the arm64 sysroot ${RINGLET_ARM64_SYSROOT}: camera backend on")
else()
  set(RINGLET_HAVE_OPENCV OFF)
  if(RINGLET_ARM64_SYSROOT)
    message(STATUS "No OpenCV for this target: RINGLET_ARM64_SYSROOT=${RINGLET_ARM64_SYSROOT} is not a finished "
                   "sysroot (tools/arm64_sysroot.sh makes it): no camera backend")
  else()
    message(STATUS "No OpenCV for this target (RINGLET_ARM64_SYSROOT is not set; tools/arm64_sysroot.sh makes "
                   "the sysroot): no camera backend")
  endif()
endif()

# ringlet_opencv_executable(TARGET...): for the executables that load OpenCV, with the sysroot
# (a no-op elsewhere). Linking: the libraries OpenCV's need (libgdal, libavcodec, ...) are in the
# sysroot too (-rpath-link). Running from the build tree under qemu-aarch64 (no -L): a build rpath
# to the same folders, as DT_RPATH (--disable-new-dtags; the toolchain writes DT_RUNPATH, which
# would serve only the binary's own NEEDED entries, not OpenCV's). Set on the executable because
# CMake 3.25 does not pass link options on through a static library's private links.
# `cmake --install` and cpack drop the build rpath: the robot gets Debian's OpenCV as a package
# (the .deb depends on it), and nothing installed points into this machine.
function(ringlet_opencv_executable)
  if(RINGLET_OPENCV_LIBDIRS)
    list(JOIN RINGLET_OPENCV_LIBDIRS ":" dirs)
    foreach(t IN LISTS ARGN)
      target_link_options(${t} PRIVATE "LINKER:-rpath-link,${dirs}" "LINKER:--disable-new-dtags")
      set_property(TARGET ${t} APPEND PROPERTY BUILD_RPATH ${RINGLET_OPENCV_LIBDIRS})
    endforeach()
  endif()
endfunction()

# The desktop tools that read and write images (vision/tools, tools/dataset) and their tests: host
# builds only. They are for the developer's desk, not the robot, and under qemu each of their many
# test processes would pay OpenCV's start-up.
if(RINGLET_HAVE_OPENCV AND NOT CMAKE_CROSSCOMPILING)
  set(RINGLET_OPENCV_TOOLS ON)
else()
  set(RINGLET_OPENCV_TOOLS OFF)
endif()

# OpenCV's ml (the SVM) and objdetect (cv::HOGDescriptor) modules: only for the offline HOG
# trainer (vision/tools/train) and the tests that hold our HOG and SVM against OpenCV's.
if(RINGLET_OPENCV_TOOLS)
  find_package(OpenCV QUIET COMPONENTS core imgproc ml objdetect)
  if(OpenCV_FOUND)
    add_library(ringlet_opencv_ml INTERFACE)
    target_link_libraries(ringlet_opencv_ml INTERFACE ringlet_opencv opencv_ml opencv_objdetect)
  endif()
  set(OpenCV_FOUND ${RINGLET_HAVE_OPENCV})
endif()
