# OpenCV's core, imgproc and imgcodecs, for specimens from images
# (include/vrut/specimen/image.hpp), as the target vrut::image.
# Debian ships OpenCV's CMake package only in libopencv-dev, which pulls in
# every module (VTK, Qt, GStreamer, ...). The three modules' own -dev
# packages hold what is needed, so where the package is missing the headers
# and libraries are found directly.
# VRUT_IMAGES=OFF leaves OpenCV out (a machine without it, a GPU node say):
# vrut::image then only tells the programs so (VRUT_NO_IMAGES), vrut-rutting
# refuses --image with a reason, and vrut-specimen and the image tests are
# not built.
option(VRUT_IMAGES "Specimens from images (needs OpenCV)" ON)
add_library(vrut_image INTERFACE)
add_library(vrut::image ALIAS vrut_image)
if(NOT VRUT_IMAGES)
  target_link_libraries(vrut_image INTERFACE vrut::vrut)
  target_compile_definitions(vrut_image INTERFACE VRUT_NO_IMAGES)
  return()
endif()
find_package(OpenCV 4 QUIET COMPONENTS core imgproc imgcodecs)
if(OpenCV_FOUND)
  target_include_directories(vrut_image INTERFACE ${OpenCV_INCLUDE_DIRS})
  target_link_libraries(vrut_image INTERFACE vrut::vrut opencv_core opencv_imgproc opencv_imgcodecs)
else()
  find_path(VRUT_OPENCV_INCLUDE_DIR opencv2/imgcodecs.hpp PATH_SUFFIXES opencv4)
  find_library(VRUT_OPENCV_CORE opencv_core)
  find_library(VRUT_OPENCV_IMGPROC opencv_imgproc)
  find_library(VRUT_OPENCV_IMGCODECS opencv_imgcodecs)
  if(NOT VRUT_OPENCV_INCLUDE_DIR OR NOT VRUT_OPENCV_CORE OR NOT VRUT_OPENCV_IMGPROC OR NOT VRUT_OPENCV_IMGCODECS)
    message(FATAL_ERROR "OpenCV (core, imgproc, imgcodecs) not found: on Debian, apt-get install "
                        "libopencv-imgproc-dev libopencv-imgcodecs-dev (scripts/setup.sh does)")
  endif()
  target_include_directories(vrut_image SYSTEM INTERFACE ${VRUT_OPENCV_INCLUDE_DIR})
  target_link_libraries(vrut_image INTERFACE vrut::vrut ${VRUT_OPENCV_IMGCODECS} ${VRUT_OPENCV_IMGPROC} ${VRUT_OPENCV_CORE})
endif()
