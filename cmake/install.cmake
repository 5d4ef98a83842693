# `cmake --install`: the package other projects find with find_package(visors).
#   <prefix>/include/visors/<layer>/*.hpp    the headers (#include <visors/nav/cdgps_filter.hpp>)
#   <prefix>/lib/libvisors_*.a                the libraries, targets visors::<layer>
#   <prefix>/lib/cmake/visors/                visorsConfig.cmake, its version file, the targets
#   <prefix>/bin/visors, visors-fsw           the program, the flight software as a process
#   <prefix>/share/visors/data/               the reference data (data/SOURCES.md), on the data
#                                             search path of the installed libraries
include(CMakePackageConfigHelpers)

get_property(visors_libraries GLOBAL PROPERTY VISORS_LIBRARIES)
install(TARGETS ${visors_libraries} EXPORT visorsTargets
  ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
  LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
  INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(TARGETS visors visors-fsw RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/src/visors/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/visors
  FILES_MATCHING PATTERN "*.hpp")
install(FILES ${PROJECT_BINARY_DIR}/generated/visors/core/version.hpp
  DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/visors/core)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/data/ DESTINATION ${CMAKE_INSTALL_DATADIR}/visors/data)

set(visors_config_dir ${CMAKE_INSTALL_LIBDIR}/cmake/visors)
install(EXPORT visorsTargets NAMESPACE visors:: DESTINATION ${visors_config_dir})
set(VISORS_PACKAGE_WITH_MPI ${MPI_CXX_FOUND})
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/visorsConfig.cmake.in
  ${PROJECT_BINARY_DIR}/visorsConfig.cmake INSTALL_DESTINATION ${visors_config_dir})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/visorsConfigVersion.cmake
  VERSION ${PROJECT_VERSION} COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/visorsConfig.cmake ${PROJECT_BINARY_DIR}/visorsConfigVersion.cmake
  DESTINATION ${visors_config_dir})
