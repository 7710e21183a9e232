# Run by `cmake --install` (cmake/install.cmake, which lists the headers in
# BILLIARD_HEADER_ENTRIES as "ROOT|PATH"): copies each header to include/billiard/PATH with its
# includes of the project ("sim/physics/...", "lcmtypes/billiard/...") prefixed by billiard/, the
# way a user includes them, so that no include of ours resolves against a user's own folders.
set(destination "$ENV{DESTDIR}${CMAKE_INSTALL_PREFIX}/${BILLIARD_INCLUDE_DIR}/billiard")
foreach(entry IN LISTS BILLIARD_HEADER_ENTRIES)
  string(REPLACE "|" ";" parts "${entry}")
  list(GET parts 0 root)
  list(GET parts 1 header)
  file(READ "${root}/${header}" text)
  string(REGEX REPLACE "#include \"(sim|planner|estimator|lcmtypes)/" "#include \"billiard/\\1/"
         text "${text}")
  set(target "${destination}/${header}")
  # Unchanged headers keep their time stamps, as install(FILES) keeps those of its files.
  if(EXISTS "${target}")
    file(READ "${target}" installed)
    if(installed STREQUAL text)
      message(STATUS "Up-to-date: ${target}")
      continue()
    endif()
  endif()
  message(STATUS "Installing: ${target}")
  file(WRITE "${target}" "${text}")
endforeach()
