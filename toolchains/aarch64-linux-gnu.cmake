# Cross build for the vehicle's compute module (arm64, Debian 12): g++-aarch64-linux-gnu against an
# arm64 sysroot made from Debian packages by tools/cross/make-sysroot.sh; binaries built for tests run
# under qemu-aarch64-static (CMAKE_CROSSCOMPILING_EMULATOR), so ctest and gtest discovery work on x86.
# tools/cross/build-aarch64.sh does all of it.
#   cmake -S . -B build-aarch64 -G Ninja -DCMAKE_TOOLCHAIN_FILE=toolchains/aarch64-linux-gnu.cmake \
#         -DDEEPNAV_SYSROOT=$PWD/build-aarch64-sysroot
set(CMAKE_SYSTEM_NAME Linux)
set(CMAKE_SYSTEM_PROCESSOR aarch64)
set(CMAKE_C_COMPILER aarch64-linux-gnu-gcc)
set(CMAKE_CXX_COMPILER aarch64-linux-gnu-g++)
set(CMAKE_LIBRARY_ARCHITECTURE aarch64-linux-gnu)

if(NOT DEEPNAV_SYSROOT)
  set(DEEPNAV_SYSROOT "$ENV{DEEPNAV_SYSROOT}")
endif()
if(NOT DEEPNAV_SYSROOT OR NOT EXISTS "${DEEPNAV_SYSROOT}/usr/include")
  message(FATAL_ERROR "aarch64: set DEEPNAV_SYSROOT to the arm64 sysroot (tools/cross/make-sysroot.sh)")
endif()
# try_compile projects see the same sysroot.
list(APPEND CMAKE_TRY_COMPILE_PLATFORM_VARIABLES DEEPNAV_SYSROOT)
set(CMAKE_SYSROOT "${DEEPNAV_SYSROOT}")
set(CMAKE_FIND_ROOT_PATH "${DEEPNAV_SYSROOT}")
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)

# pkg-config (zstd, lz4, libmodbus, aravis) reads the sysroot's .pc files and prefixes their paths.
set(ENV{PKG_CONFIG_SYSROOT_DIR} "${DEEPNAV_SYSROOT}")
set(ENV{PKG_CONFIG_LIBDIR}
    "${DEEPNAV_SYSROOT}/usr/lib/aarch64-linux-gnu/pkgconfig:${DEEPNAV_SYSROOT}/usr/share/pkgconfig:${DEEPNAV_SYSROOT}/usr/lib/pkgconfig")
set(ENV{PKG_CONFIG_PATH} "")

# Test binaries run under user-mode QEMU with the sysroot as their root for the loader and libraries.
set(CMAKE_CROSSCOMPILING_EMULATOR qemu-aarch64-static -L "${DEEPNAV_SYSROOT}")
