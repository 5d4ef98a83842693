# 64-bit ARM (Cortex-A53 class): Debian's aarch64-linux-gnu cross compiler, the programs run by
# qemu-aarch64 on the cross compiler's own C and C++ libraries. VISORS_TARGET_SYSROOT: where
# scripts/cross_test.sh unpacked the target's ERFA.
set(VISORS_TARGET_TRIPLET aarch64-linux-gnu)
set(VISORS_QEMU qemu-aarch64)
set(CMAKE_SYSTEM_PROCESSOR aarch64)
include(${CMAKE_CURRENT_LIST_DIR}/debian_cross.cmake)
