# Fails when a pure library includes what it must not: nav/ and vision/ never include drivers/, board/
# or tools/; drivers/ never includes board/ or tools/ (../shared/DESIGN.md, "Dependencies point one way").
function(check_folder folder forbidden_regex)
  file(GLOB_RECURSE sources "${ROOT}/${folder}/*.h" "${ROOT}/${folder}/*.cpp")
  foreach(src ${sources})
    file(STRINGS "${src}" lines REGEX "#include \"(${forbidden_regex})/")
    if(lines)
      message(SEND_ERROR "${src}: ${folder}/ must not include ${forbidden_regex}: ${lines}")
    endif()
  endforeach()
endfunction()
check_folder(nav "drivers|board|tools")
check_folder(vision "drivers|board|tools")
check_folder(drivers "board|tools")
