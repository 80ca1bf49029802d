# Install-time step of cmake/install.cmake: in the installed headers, an #include of a library
# folder in the short style ("core/errors.h") becomes "bezierpde/core/errors.h". Idempotent: lines
# already in the bezierpde/ style do not match. Inputs: BPDE_INSTALLED_INCLUDE_DIR (relative to the
# prefix) and BPDE_HEADER_FOLDERS, set by install(CODE) just before.
string(REPLACE ";" "|" folders "${BPDE_HEADER_FOLDERS}")
file(GLOB_RECURSE headers "$ENV{DESTDIR}${CMAKE_INSTALL_PREFIX}/${BPDE_INSTALLED_INCLUDE_DIR}/bezierpde/*.h")
set(count 0)
foreach(h ${headers})
  file(READ "${h}" text)
  string(REGEX REPLACE "(#[ \t]*include[ \t]*\")(${folders})/" "\\1bezierpde/\\2/" new_text "${text}")
  if(NOT new_text STREQUAL text)
    file(WRITE "${h}" "${new_text}")
    math(EXPR count "${count} + 1")
  endif()
endforeach()
message(STATUS "bezierpde: include lines of ${count} installed header(s) put in the bezierpde/ style")
