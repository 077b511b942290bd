# `cmake --install`: the granule command, its plot scripts, and the libraries with their headers
# as a CMake package, so that another project does
#   find_package(granule)  and  target_link_libraries(app PRIVATE granule::core)
# (README.md, "Install / use as a library"; ARCHITECTURE.md, "Installed package").
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(GRANULE_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/granule)

# The libraries a consumer links, as granule::<component>: the engine (core, no dependency),
# theory (Eigen), analysis (Eigen, Boost.Math), io (HDF5, toml++, JSON, fmt) and driver (one run
# with its outputs).  The command line's own libraries (app, sweep, render) stay inside the binary.
set(GRANULE_EXPORTED_LIBRARIES granule_core granule_theory granule_analysis granule_io granule_driver)
foreach(library ${GRANULE_EXPORTED_LIBRARIES})
  string(REPLACE "granule_" "" component ${library})
  set_target_properties(${library} PROPERTIES EXPORT_NAME ${component})
  add_library(granule::${component} ALIAS ${library})
endforeach()

install(TARGETS granule RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(TARGETS ${GRANULE_EXPORTED_LIBRARIES} EXPORT granuleTargets ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
# Headers keep their folders (include/granule/engine/simulation.hpp); the command line's are not
# part of the library.
install(DIRECTORY src/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/granule FILES_MATCHING PATTERN "*.hpp"
        PATTERN "app" EXCLUDE PATTERN "sweep" EXCLUDE PATTERN "render" EXCLUDE)
install(FILES ${CMAKE_BINARY_DIR}/generated/granule/version.hpp DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/granule)
# The binary finds them at <prefix>/bin/../${GRANULE_INSTALL_PYTHON_DIR} (src/render/plot_scripts.cpp).
install(DIRECTORY python/granule_plots DESTINATION ${GRANULE_INSTALL_PYTHON_DIR} PATTERN "__pycache__" EXCLUDE)

install(EXPORT granuleTargets NAMESPACE granule:: DESTINATION ${GRANULE_CMAKE_DIR})
configure_package_config_file(cmake/granuleConfig.cmake.in ${CMAKE_BINARY_DIR}/granuleConfig.cmake
                              INSTALL_DESTINATION ${GRANULE_CMAKE_DIR})
write_basic_package_version_file(${CMAKE_BINARY_DIR}/granuleConfigVersion.cmake COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_BINARY_DIR}/granuleConfig.cmake ${CMAKE_BINARY_DIR}/granuleConfigVersion.cmake
        DESTINATION ${GRANULE_CMAKE_DIR})
