# OpenCV, for the camera backend and the desktop tools (image files, Canny + HoughLinesP as a
# baseline); never for the algorithms, which run on the robot inside their budgets.
#
# The host build requires it (libopencv-dev). The aarch64 cross build goes without: Debian's
# libopencv-imgcodecs/videoio :arm64 packages cannot be installed next to the amd64 ones, so a
# cross build here has no OpenCV and builds neither the camera backend nor the tools. A build in
# an arm64 sysroot (or on the robot) with libopencv-dev installed gets them. RINGLET_HAVE_OPENCV
# says which.
if(CMAKE_CROSSCOMPILING)
  find_package(OpenCV QUIET COMPONENTS core imgproc imgcodecs videoio)
else()
  find_package(OpenCV REQUIRED COMPONENTS core imgproc imgcodecs videoio)
endif()
set(RINGLET_HAVE_OPENCV ${OpenCV_FOUND})
if(OpenCV_FOUND)
  add_library(ringlet_opencv INTERFACE)
  target_link_libraries(ringlet_opencv INTERFACE ${OpenCV_LIBS})
  target_include_directories(ringlet_opencv SYSTEM INTERFACE ${OpenCV_INCLUDE_DIRS})
else()
  message(STATUS "OpenCV not found for this target: no camera backend, no vision tools")
endif()

# OpenCV's ml (the SVM) and objdetect (cv::HOGDescriptor) modules: only for the offline HOG
# trainer (vision/tools/train) and the tests that hold our HOG and SVM against OpenCV's.
if(OpenCV_FOUND)
  find_package(OpenCV QUIET COMPONENTS core imgproc ml objdetect)
  if(OpenCV_FOUND)
    add_library(ringlet_opencv_ml INTERFACE)
    target_link_libraries(ringlet_opencv_ml INTERFACE ringlet_opencv opencv_ml opencv_objdetect)
  endif()
  set(OpenCV_FOUND ${RINGLET_HAVE_OPENCV})
endif()
