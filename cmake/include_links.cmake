# bpde_include_links(<source root> <include dir>): the include style "bezierpde/<folder>/<name>.h"
# (docs/ARCHITECTURE.md) in a build tree: <include dir>/bezierpde/<folder> is a symbolic link to
# <source root>/<folder> for every header folder of the library. A link that points elsewhere (a
# build tree configured from another checkout, a moved source tree) is made again, so the build
# never compiles another tree's headers. Used by the main CMakeLists.txt and fuzz/CMakeLists.txt.
set(BPDE_HEADER_FOLDERS core tensor triangular energies solvers boundaries io jobs checks complex)

function(bpde_include_links source_root include_dir)
  file(MAKE_DIRECTORY ${include_dir}/bezierpde)
  foreach(folder ${BPDE_HEADER_FOLDERS})
    set(link ${include_dir}/bezierpde/${folder})
    set(link_target "")
    if(IS_SYMLINK ${link})
      file(READ_SYMLINK ${link} link_target)
      if(NOT link_target STREQUAL "${source_root}/${folder}")
        file(REMOVE ${link})
      endif()
    elseif(EXISTS ${link})
      file(REMOVE_RECURSE ${link})
    endif()
    if(NOT link_target STREQUAL "${source_root}/${folder}")
      file(CREATE_LINK ${source_root}/${folder} ${link} SYMBOLIC)
    endif()
  endforeach()
endfunction()
