# The API reference (docs/Doxyfile.in): a target `docs` where Debian's
# doxygen is found, over the public headers users call. The suite runs the
# same configuration with warnings as errors (tests/CMakeLists.txt).
find_package(Doxygen QUIET)
if(NOT DOXYGEN_FOUND)
  message(STATUS "vrut: doxygen not found, no 'docs' target (apt-get install doxygen)")
  return()
endif()
set(VRUT_DOCUMENTED_HEADERS
  contact/concept.hpp contact/composite.hpp contact/geometry.hpp contact/linear.hpp contact/burgers.hpp
  contact/film.hpp contact/choice.hpp
  core/simulation.hpp core/settings.hpp
  data/dimension.hpp data/vec2.hpp data/vec3.hpp data/particle_set.hpp data/walls.hpp data/walls3.hpp
  protocol/rutting/test.hpp protocol/rutting/result.hpp protocol/rutting/driver.hpp protocol/rutting/run.hpp
  protocol/rutting/run3.hpp
  specimen/specimen.hpp specimen/specimen3.hpp)
set(VRUT_DOCS_INPUT "")
foreach(header ${VRUT_DOCUMENTED_HEADERS})
  string(APPEND VRUT_DOCS_INPUT " ${PROJECT_SOURCE_DIR}/include/vrut/${header}")
endforeach()
set(VRUT_DOCS_OUTPUT ${PROJECT_BINARY_DIR}/docs)
set(VRUT_DOCS_WARN_AS_ERROR NO)
configure_file(${PROJECT_SOURCE_DIR}/docs/Doxyfile.in ${PROJECT_BINARY_DIR}/docs/Doxyfile @ONLY)
set(VRUT_DOCS_OUTPUT ${PROJECT_BINARY_DIR}/docs-check)
set(VRUT_DOCS_WARN_AS_ERROR FAIL_ON_WARNINGS)
configure_file(${PROJECT_SOURCE_DIR}/docs/Doxyfile.in ${PROJECT_BINARY_DIR}/docs-check/Doxyfile @ONLY)
add_custom_target(docs COMMAND Doxygen::doxygen ${PROJECT_BINARY_DIR}/docs/Doxyfile
  WORKING_DIRECTORY ${PROJECT_BINARY_DIR}/docs COMMENT "vrut API reference: build/docs/html/index.html" VERBATIM)
