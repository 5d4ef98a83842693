# 32-bit ARM, hard float (Cortex-A7/A9 class): Debian's arm-linux-gnueabihf cross compiler, the
# programs run by qemu-arm on the cross compiler's own C and C++ libraries. VISORS_TARGET_SYSROOT:
# where scripts/cross_test.sh unpacked the target's ERFA.
set(VISORS_TARGET_TRIPLET arm-linux-gnueabihf)
set(VISORS_QEMU qemu-arm)
set(CMAKE_SYSTEM_PROCESSOR arm)
include(${CMAKE_CURRENT_LIST_DIR}/debian_cross.cmake)
