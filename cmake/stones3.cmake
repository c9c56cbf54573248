# Qhull (convex hulls) and libccd (overlap of convex shapes), for the 3D
# specimen's polyhedral stones (include/vrut/specimen/stone3.hpp), as the
# target vrut::stones3. Debian: libqhull-dev, libccd-dev (scripts/setup.sh).
find_package(Qhull CONFIG QUIET)
find_package(ccd CONFIG QUIET)
if(NOT Qhull_FOUND OR NOT ccd_FOUND)
  message(FATAL_ERROR "Qhull and libccd not found: on Debian, apt-get install libqhull-dev libccd-dev "
                      "(scripts/setup.sh does)")
endif()
add_library(vrut_stones3 INTERFACE)
add_library(vrut::stones3 ALIAS vrut_stones3)
target_link_libraries(vrut_stones3 INTERFACE vrut::vrut Qhull::qhullcpp Qhull::qhull_r ccd)
