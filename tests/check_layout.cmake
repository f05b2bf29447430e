# Fails when a library includes a layer it must not. Dependencies point one way (README.md, "Layout"):
#   base/        the ground floor (SO(3), marker observations): includes no other project folder;
#   nav/         estimation: base/ and nav/, never vision/;
#   nav/types/   the sample types: base/ and nav/types/ only (they sit below the rest of nav);
#   vision/      image processing: base/, vision/ and the sample types nav/types/ only;
#   drivers/     never board/ or tools/; board/ never tools/. No library includes tests/ (test scaffolding
#                such as the synthetic scenes lives in tests/support, target test_support).
# Run: cmake -DROOT=<project root> -P tests/check_layout.cmake (ctest: layout_dependency_direction).
if(NOT ROOT)
  get_filename_component(ROOT "${CMAKE_CURRENT_LIST_DIR}/.." ABSOLUTE)
endif()

# Every '#include "<dir>/..."' in the sources under folder/ with <dir> matching forbidden_regex, except
# the lines that match allowed_regex (optional third argument), is an error.
function(check_folder folder forbidden_regex)
  file(GLOB_RECURSE sources "${ROOT}/${folder}/*.h" "${ROOT}/${folder}/*.cpp")
  if(NOT sources)
    message(SEND_ERROR "${ROOT}/${folder}/ holds no sources: wrong ROOT?")
  endif()
  foreach(src ${sources})
    file(STRINGS "${src}" lines REGEX "#include \"(${forbidden_regex})/")
    if(lines AND ARGC GREATER 2)
      list(FILTER lines EXCLUDE REGEX "${ARGV2}")
    endif()
    if(lines)
      message(SEND_ERROR "${src}: ${folder}/ must not include ${forbidden_regex}: ${lines}")
    endif()
  endforeach()
endfunction()

check_folder(base "nav|vision|drivers|board|tools|tests")
check_folder(nav "vision|drivers|board|tools|tests")
check_folder(nav/types "nav|vision|drivers|board|tools|tests" "#include \"nav/types/")
check_folder(vision "nav|drivers|board|tools|tests" "#include \"nav/types/")
check_folder(drivers "board|tools|tests")
check_folder(board "tools|tests")
