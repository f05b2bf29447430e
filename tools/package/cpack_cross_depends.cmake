# CPack project config file of a cross build (read when cpack runs, after the binary is built): sets
# the arm64 package's Depends from the binary's NEEDED libraries (tools/package/cross_depends.sh).
if(CPACK_GENERATOR STREQUAL "DEB")
  execute_process(COMMAND ${CPACK_DEEPNAV_CROSS_DEPENDS_SCRIPT} ${CPACK_DEEPNAV_BINARY}
                  OUTPUT_VARIABLE deepnav_depends OUTPUT_STRIP_TRAILING_WHITESPACE RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0 OR deepnav_depends STREQUAL "")
    message(FATAL_ERROR "cpack: no Depends for ${CPACK_DEEPNAV_BINARY} (cross_depends.sh exit ${rc})")
  endif()
  set(CPACK_DEBIAN_PACKAGE_DEPENDS "${deepnav_depends}")
endif()
