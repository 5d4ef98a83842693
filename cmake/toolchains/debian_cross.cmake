# A Debian cross toolchain for VISORS_TARGET_TRIPLET (set by armhf.cmake / aarch64.cmake): the
# cross compiler, its C and C++ libraries under /usr/<triplet> (no foreign architecture in dpkg),
# the target's ERFA unpacked into VISORS_TARGET_SYSROOT (its pkg-config file read from there) and
# qemu-user as the emulator through which CMake's test discovery and CTest run the programs.
set(CMAKE_SYSTEM_NAME Linux)
set(CMAKE_C_COMPILER ${VISORS_TARGET_TRIPLET}-gcc)
set(CMAKE_CXX_COMPILER ${VISORS_TARGET_TRIPLET}-g++)
if(NOT VISORS_TARGET_SYSROOT)
  set(VISORS_TARGET_SYSROOT $ENV{VISORS_TARGET_SYSROOT})
endif()
if(NOT VISORS_TARGET_SYSROOT)
  message(FATAL_ERROR "VISORS_TARGET_SYSROOT: not set (the directory holding the target's ERFA; scripts/cross_test.sh sets it)")
endif()
# The compiler checks re-read this file in their own projects, where the variable must be too
# (and the environment below is the whole process's).
list(APPEND CMAKE_TRY_COMPILE_PLATFORM_VARIABLES VISORS_TARGET_SYSROOT)
set(CMAKE_FIND_ROOT_PATH ${VISORS_TARGET_SYSROOT} /usr/${VISORS_TARGET_TRIPLET})
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE BOTH)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE BOTH)  # Eigen's and nlohmann_json's CMake files: headers only
set(ENV{PKG_CONFIG_LIBDIR} ${VISORS_TARGET_SYSROOT}/usr/lib/${VISORS_TARGET_TRIPLET}/pkgconfig)
set(ENV{PKG_CONFIG_SYSROOT_DIR} ${VISORS_TARGET_SYSROOT})
set(CMAKE_CROSSCOMPILING_EMULATOR ${VISORS_QEMU} -L /usr/${VISORS_TARGET_TRIPLET})
set(CMAKE_BUILD_RPATH ${VISORS_TARGET_SYSROOT}/usr/lib/${VISORS_TARGET_TRIPLET})
