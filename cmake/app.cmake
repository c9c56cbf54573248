# The application layer (include/vrut/app/, host only): the rutting test's
# options, run, report and pictures, which vrut-rutting and the Python module
# share, as the target vrut::app. It needs what the programs need: CLI11,
# nlohmann-json, cairo (the pictures), OpenCV where VRUT_IMAGES (vrut::image)
# and Qhull/libccd (vrut::stones3).
find_package(PkgConfig REQUIRED)
pkg_check_modules(CAIRO REQUIRED IMPORTED_TARGET cairo)
add_library(vrut_app INTERFACE)
add_library(vrut::app ALIAS vrut_app)
target_link_libraries(vrut_app INTERFACE vrut::vrut vrut::image vrut::stones3 CLI11::CLI11
                      nlohmann_json::nlohmann_json PkgConfig::CAIRO)
