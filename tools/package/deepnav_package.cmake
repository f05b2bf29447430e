# The deepnav Debian package (CPack DEB): `cmake --build BUILD --target package` writes
# BUILD/deepnav_<version>_<arch>.deb with
#   /usr/bin/deepnav                          the firmware
#   /usr/lib/systemd/system/deepnav.service   the unit (board/systemd/deepnav.service)
#   /etc/deepnav/board.yaml, panel.yaml       the default board: the simulator's rig (board/sim), replaying
#                                             /var/lib/deepnav/dive.mcap (conffiles)
#   /usr/share/deepnav/boards/                board/sim and board/example-vehicle, for reference
#   /usr/share/doc/deepnav/README.md          board/service/README.md
# tools/package/test_deb.sh installs it into a clean Debian 12 chroot and runs it there.
# `ninja deepnav && cpack` must not build every test first.
set(CMAKE_SKIP_INSTALL_ALL_DEPENDENCY ON)
install(TARGETS deepnav RUNTIME DESTINATION bin)
install(FILES ${PROJECT_SOURCE_DIR}/board/systemd/deepnav.service DESTINATION lib/systemd/system)

# The default board is the simulator's rig with its paths moved to where the package keeps data.
file(READ ${PROJECT_SOURCE_DIR}/board/sim/board.yaml DEEPNAV_DEFAULT_BOARD)
string(REGEX REPLACE "replay_path: [^ \n]+" "replay_path: /var/lib/deepnav/dive.mcap"
       DEEPNAV_DEFAULT_BOARD "${DEEPNAV_DEFAULT_BOARD}")
string(REGEX REPLACE "recording_dir: [^ \n]+" "recording_dir: /var/lib/deepnav/recordings"
       DEEPNAV_DEFAULT_BOARD "${DEEPNAV_DEFAULT_BOARD}")
file(WRITE ${PROJECT_BINARY_DIR}/package/board.yaml "${DEEPNAV_DEFAULT_BOARD}")
set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/board/sim/board.yaml)
install(FILES ${PROJECT_BINARY_DIR}/package/board.yaml ${PROJECT_SOURCE_DIR}/board/sim/panel.yaml
        DESTINATION /etc/deepnav)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/board/sim ${PROJECT_SOURCE_DIR}/board/example-vehicle
        DESTINATION share/deepnav/boards)
install(FILES ${PROJECT_SOURCE_DIR}/board/service/README.md DESTINATION share/doc/deepnav)

set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME deepnav)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_CONTACT "deepnav maintainers <deepnav@example.org>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "ROV navigation firmware: panel-relative EKF, stereo vision, vehicle outputs")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_WARN_ON_ABSOLUTE_INSTALL_DESTINATION OFF)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION misc)
# Runtime libraries from dpkg-shlibdeps (native builds). A cross build has no dpkg database for its
# sysroot: tools/package/cpack_cross_depends.cmake derives the Depends from the built binary's NEEDED
# libraries through the host's packages of the same Debian release (tools/package/cross_depends.sh).
if(CMAKE_CROSSCOMPILING)
  set(CPACK_DEBIAN_PACKAGE_ARCHITECTURE arm64)
  set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS OFF)
  set(CPACK_DEEPNAV_BINARY ${CMAKE_RUNTIME_OUTPUT_DIRECTORY}/deepnav)
  set(CPACK_DEEPNAV_CROSS_DEPENDS_SCRIPT ${PROJECT_SOURCE_DIR}/tools/package/cross_depends.sh)
  set(CPACK_PROJECT_CONFIG_FILE ${PROJECT_SOURCE_DIR}/tools/package/cpack_cross_depends.cmake)
else()
  set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
endif()
set(CPACK_DEBIAN_PACKAGE_CONTROL_EXTRA
    ${PROJECT_SOURCE_DIR}/tools/package/conffiles ${PROJECT_SOURCE_DIR}/tools/package/postinst
    ${PROJECT_SOURCE_DIR}/tools/package/postrm)
set(CPACK_DEBIAN_PACKAGE_CONTROL_STRICT_PERMISSION ON)
include(CPack)
