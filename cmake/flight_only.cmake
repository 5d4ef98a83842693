# The flight layers alone (VISORS_FLIGHT_ONLY), for the ARM cross-builds under qemu-user
# (scripts/cross_test.sh, cmake/toolchains/): core, astro, dynamics, gnss, optim, nav, control,
# safety and gnc with the ground readers their tests link (the layers' files/ folders), and the
# flight tests of tests/CMakeLists.txt. Needs only Eigen and nlohmann_json (headers), ERFA for the
# target (the toolchain's VISORS_TARGET_SYSROOT) and GoogleTest's sources, built here for the
# target. Nothing of the ground: no program, Python, install, benchmarks or documentation.
find_package(Eigen3 3.4 REQUIRED NO_MODULE)
find_package(PkgConfig REQUIRED)
pkg_check_modules(ERFA REQUIRED IMPORTED_TARGET erfa)
find_package(nlohmann_json 3 REQUIRED)

set(VISORS_GOOGLETEST_SOURCE /usr/src/googletest CACHE PATH "GoogleTest's sources (Debian's googletest package)")
set(BUILD_GMOCK OFF CACHE BOOL "" FORCE)
set(INSTALL_GTEST OFF CACHE BOOL "" FORCE)
add_subdirectory(${VISORS_GOOGLETEST_SOURCE} ${PROJECT_BINARY_DIR}/googletest EXCLUDE_FROM_ALL SYSTEM)
target_compile_options(gtest PRIVATE -w)  # GoogleTest's own sources: not this project's warnings
target_compile_options(gtest_main PRIVATE -w)
# GCC 12 reports a false -Wrestrict overlap in std::string's inlined copies (GCC bug 105329),
# which the 32-bit target's size_t brings out in the layers' error messages; the host and aarch64
# builds keep the warning.
if(CMAKE_SIZEOF_VOID_P EQUAL 4 AND CMAKE_CXX_COMPILER_ID STREQUAL "GNU" AND CMAKE_CXX_COMPILER_VERSION VERSION_LESS 13)
  target_compile_options(visors_warnings INTERFACE -Wno-restrict)
endif()

enable_testing()
include(GNUInstallDirs)
include(cmake/visors_library.cmake)
foreach(layer core astro dynamics gnss optim nav control safety gnc)
  add_subdirectory(src/visors/${layer})
endforeach()
add_subdirectory(apps/fsw)
add_subdirectory(tests)
