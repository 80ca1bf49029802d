# The package test (CTest "Package.consumer"): install bezierpde from the build tree into a
# temporary prefix, assemble an outside project from the README (its CMake snippet as the project's
# CMakeLists.txt, its C++ "Library use" snippets compiled verbatim), configure it against the
# prefix with find_package(bezierpde 0.2 CONFIG REQUIRED), build it and run it.
#
#   cmake -DSOURCE_DIR=... -DBUILD_DIR=... -DWORK_DIR=... -DCXX_COMPILER=... [-DLAUNCHER=...]
#         -DGENERATOR=... [-DSHARED=ON|OFF] [-DSANITIZE=address,undefined]
#         [-DPYTHON=<interpreter> -DPYTHON_SITE=<site-packages relative to the prefix>] -P tests/package/run_consumer.cmake
#
# With SHARED (the build's BUILD_SHARED_LIBS) the installed lib/ must hold the libbpde_*.so files and
# the consumer's programs and the installed bpde must load every libbpde_*.so from the prefix (ldd),
# none from the build tree, with no RUNPATH into the build tree; without it, they must not depend on
# any libbpde_*.so.
#
# README snippets are fenced code blocks between the markers
#   <!-- snippet: NAME -->  ...  <!-- /snippet -->
# NAME "cmake" is the consumer's CMakeLists.txt; every other snippet is C++: its #include lines
# stay at file scope, the rest becomes the body of void snippet_NAME(), and main() runs them in
# README order from a folder holding net.json (a tensor net) and job.json (a cmc job).
cmake_minimum_required(VERSION 3.22)
foreach(v SOURCE_DIR BUILD_DIR WORK_DIR CXX_COMPILER GENERATOR)
  if(NOT DEFINED ${v})
    message(FATAL_ERROR "run_consumer.cmake: -D${v}= is required")
  endif()
endforeach()

function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    string(REPLACE ";" " " cmd "${ARGN}")
    message(FATAL_ERROR "failed (${rc}): ${cmd}\n${out}\n${err}")
  endif()
  set(last_output "${out}" PARENT_SCOPE)
endfunction()

file(REMOVE_RECURSE ${WORK_DIR})
set(prefix ${WORK_DIR}/prefix)
set(consumer ${WORK_DIR}/consumer)
set(run_dir ${WORK_DIR}/run)
file(MAKE_DIRECTORY ${consumer} ${run_dir})

# 1. Install (copies only: the build tree is already built).
run(${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix})
foreach(f include/bezierpde/jobs/run_job.h include/bezierpde/core/errors.h bin/bpde
          lib/cmake/bezierpde/bezierpdeConfig.cmake lib/cmake/bezierpde/bezierpdeConfigVersion.cmake)
  if(NOT EXISTS ${prefix}/${f})
    message(FATAL_ERROR "not installed: ${f}")
  endif()
endforeach()
# No header outside include/bezierpde/, and none that still includes a library folder directly.
file(GLOB top LIST_DIRECTORIES true RELATIVE ${prefix}/include ${prefix}/include/*)
if(NOT top STREQUAL "bezierpde")
  message(FATAL_ERROR "installed include/ holds more than bezierpde/: ${top}")
endif()
file(GLOB_RECURSE headers ${prefix}/include/bezierpde/*.h)
foreach(h ${headers})
  file(STRINGS ${h} bad REGEX "^#include \"(core|tensor|triangular|energies|solvers|boundaries|io|jobs|checks)/")
  if(bad)
    message(FATAL_ERROR "${h} includes a library header outside bezierpde/: ${bad}")
  endif()
endforeach()

# 2. The consumer project from the README.
file(READ ${SOURCE_DIR}/README.md readme)
set(names "")
set(rest "${readme}")
while(TRUE)
  string(FIND "${rest}" "<!-- snippet: " start)
  if(start EQUAL -1)
    break()
  endif()
  string(SUBSTRING "${rest}" ${start} -1 rest)
  string(REGEX MATCH "^<!-- snippet: ([a-z0-9_]+) -->" head "${rest}")
  set(name ${CMAKE_MATCH_1})
  string(FIND "${rest}" "<!-- /snippet -->" stop)
  if(NOT name OR stop EQUAL -1)
    message(FATAL_ERROR "README.md: a snippet marker without a name or an end")
  endif()
  string(SUBSTRING "${rest}" 0 ${stop} block)
  string(SUBSTRING "${rest}" ${stop} -1 rest)
  # The fenced code inside the markers.
  string(REGEX MATCH "```[a-z]*\n(.*)```" fenced "${block}")
  set(code "${CMAKE_MATCH_1}")
  if(NOT code)
    message(FATAL_ERROR "README.md: snippet ${name} holds no fenced code")
  endif()
  list(APPEND names ${name})
  set(snippet_${name} "${code}")
endwhile()
if(NOT "cmake" IN_LIST names)
  message(FATAL_ERROR "README.md: no CMake snippet (<!-- snippet: cmake -->)")
endif()
list(LENGTH names count)
if(count LESS 3)
  message(FATAL_ERROR "README.md: expected the CMake snippet and at least two C++ snippets, found ${names}")
endif()

file(READ ${SOURCE_DIR}/tests/package/consumer/extra.cmake extra)
file(WRITE ${consumer}/CMakeLists.txt "${snippet_cmake}\n${extra}")
file(COPY ${SOURCE_DIR}/tests/package/consumer/main.cpp ${SOURCE_DIR}/tests/package/consumer/nets_only.cpp
          ${SOURCE_DIR}/tests/package/consumer/core DESTINATION ${consumer})
set(inc "// Generated from README.md by tests/package/run_consumer.cmake: the snippets verbatim.\n")
set(calls "")
foreach(name ${names})
  if(name STREQUAL "cmake")
    continue()
  endif()
  # Line by line without CMake lists (the code holds semicolons and brackets).
  set(includes "")
  set(body "")
  set(text "${snippet_${name}}")
  while(NOT text STREQUAL "")
    string(FIND "${text}" "\n" nl)
    if(nl EQUAL -1)
      set(line "${text}")
      set(text "")
    else()
      string(SUBSTRING "${text}" 0 ${nl} line)
      math(EXPR nl "${nl} + 1")
      string(SUBSTRING "${text}" ${nl} -1 text)
    endif()
    if(line MATCHES "^#include")
      string(APPEND includes "${line}\n")
    else()
      string(APPEND body "  ${line}\n")
    endif()
  endwhile()
  string(APPEND inc "\n// README snippet \"${name}\"\n${includes}\nvoid snippet_${name}() {\n${body}}\n")
  string(APPEND calls "  snippet_${name}();\n")
endforeach()
string(APPEND inc "\ninline void run_readme_snippets() {\n${calls}}\n")
file(WRITE ${consumer}/snippets.inc "${inc}")

# 3. Configure against the prefix alone, build, run.
set(launcher "")
if(LAUNCHER)
  set(launcher -DCMAKE_CXX_COMPILER_LAUNCHER=${LAUNCHER})
endif()
# A sanitizer build (-DSANITIZE=address,undefined) installs instrumented archives: the consumer is
# compiled and linked with the same sanitizers, so that it links their runtime and is checked too.
set(sanitize "")
if(SANITIZE)
  set(sanitize "-DCMAKE_CXX_FLAGS=-fsanitize=${SANITIZE} -fno-omit-frame-pointer -fno-sanitize-recover=all"
               "-DCMAKE_EXE_LINKER_FLAGS=-fsanitize=${SANITIZE}")
endif()
run(${CMAKE_COMMAND} -S ${consumer} -B ${consumer}/build -G ${GENERATOR} -DCMAKE_BUILD_TYPE=Release
    -DCMAKE_CXX_COMPILER=${CXX_COMPILER} ${launcher} -DCMAKE_PREFIX_PATH=${prefix} ${sanitize})
run(${CMAKE_COMMAND} --build ${consumer}/build)

file(READ ${SOURCE_DIR}/examples/001-pde-figures/fig1-biharmonic.json pde_job)
string(JSON tensor_net GET "${pde_job}" net)
file(WRITE ${run_dir}/net.json "${tensor_net}")
file(COPY_FILE ${SOURCE_DIR}/examples/004-cmc-circle/n4-b-H-1.json ${run_dir}/job.json)
execute_process(COMMAND ${consumer}/build/app WORKING_DIRECTORY ${run_dir} RESULT_VARIABLE rc OUTPUT_VARIABLE out
                ERROR_VARIABLE err)
if(NOT rc EQUAL 0 OR NOT out MATCHES "README snippets ran")
  message(FATAL_ERROR "consumer app failed (${rc}):\n${out}\n${err}")
endif()
if(NOT EXISTS ${run_dir}/out/job/result.json)
  message(FATAL_ERROR "the run_job snippet wrote no out/job/result.json")
endif()
run(${consumer}/build/nets_only)
# The installed command runs too.
run(${prefix}/bin/bpde solve ${run_dir}/job.json --out ${run_dir}/installed-bpde)

# 4. The Python module (-DPYTHON=<interpreter> -DPYTHON_SITE=<site-packages relative to the
#    prefix>, when the build has it): installed into the prefix's site-packages, it imports from
#    there alone (PYTHONPATH=<prefix>/<site>, from a folder outside the build tree) and runs.
set(python_core "")
if(PYTHON)
  set(site ${prefix}/${PYTHON_SITE})
  file(GLOB python_core ${site}/bezierpde/_core*.so)
  if(NOT EXISTS ${site}/bezierpde/__init__.py OR NOT EXISTS ${site}/bezierpde/sweep.py OR NOT python_core)
    message(FATAL_ERROR "the Python package is not installed in ${site}/bezierpde")
  endif()
  set(ENV{PYTHONPATH} ${site})
  unset(ENV{LD_LIBRARY_PATH})
  execute_process(
    COMMAND ${PYTHON} -c
            "import os, bezierpde\n\
where = os.path.realpath(bezierpde.__file__)\n\
assert where.startswith(os.path.realpath('${site}') + os.sep), where\n\
V, F, H = bezierpde.sample(bezierpde.TriangularNet(2), samples=4)\n\
assert V.shape == (15, 3) and F.shape == (16, 3), (V.shape, F.shape)\n\
print('imported', bezierpde.__version__, 'from', where)"
    WORKING_DIRECTORY ${run_dir} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "the installed Python module does not import from ${site}:\n${out}\n${err}")
  endif()
  unset(ENV{PYTHONPATH})
endif()

# 5. Shared or static, as built: what the programs load (ldd) and where from (their RUNPATH).
find_program(LDD ldd)
find_program(READELF readelf)
if(NOT LDD OR NOT READELF)
  message(FATAL_ERROR "the package test needs ldd and readelf (libc-bin, binutils)")
endif()
# The run paths alone decide (an LD_LIBRARY_PATH of the caller's would take precedence over RUNPATH).
unset(ENV{LD_LIBRARY_PATH})
set(programs ${consumer}/build/app ${consumer}/build/nets_only ${prefix}/bin/bpde ${python_core})
set(libdir "")
if(SHARED)
  foreach(dir lib lib64 lib/x86_64-linux-gnu)
    if(EXISTS ${prefix}/${dir}/libbpde_jobs.so)
      set(libdir ${prefix}/${dir})
    endif()
  endforeach()
  if(NOT libdir)
    message(FATAL_ERROR "BUILD_SHARED_LIBS: no libbpde_jobs.so installed under ${prefix}")
  endif()
  foreach(l bpde_core bpde_solvers bpde_cmc bpde_io bpde_view bpde_step bpde_checks bpde_jobs)
    if(NOT EXISTS ${libdir}/lib${l}.so OR EXISTS ${libdir}/lib${l}.a)
      message(FATAL_ERROR "BUILD_SHARED_LIBS: expected lib${l}.so (and no lib${l}.a) in ${libdir}")
    endif()
  endforeach()
  list(APPEND programs ${libdir}/libbpde_jobs.so)
endif()
foreach(program ${programs})
  run(${LDD} ${program})
  string(REPLACE "\n" ";" deps "${last_output}")
  set(loaded "")
  foreach(line ${deps})
    if(line MATCHES "not found")
      message(FATAL_ERROR "${program}: a library is not found:\n${last_output}")
    endif()
    if(line MATCHES "libbpde_[a-z]+\\.so")
      string(STRIP "${line}" line)
      list(APPEND loaded "${line}")
      if(NOT SHARED)
        message(FATAL_ERROR "static build: ${program} loads ${line}")
      endif()
      # "libbpde_x.so.0.2 => /path/libbpde_x.so.0.2 (0x...)": the folder of the resolved path
      # (ldd prints it as the RUNPATH spells it, e.g. bin/../lib) must be the prefix's.
      set(from "")
      if(line MATCHES "=> ([^ ]+) \\(")
        get_filename_component(from "${CMAKE_MATCH_1}" DIRECTORY)
        get_filename_component(from "${from}" REALPATH)
      endif()
      get_filename_component(want "${libdir}" REALPATH)
      if(NOT from STREQUAL want)
        message(FATAL_ERROR "BUILD_SHARED_LIBS: ${program} loads ${line}, not from ${libdir}")
      endif()
    endif()
  endforeach()
  if(SHARED)
    list(LENGTH loaded count)
    # the consumer programs and bpde link the umbrella target (all eight; nets_only core alone),
    # libbpde_jobs.so the other seven
    if(count EQUAL 0)
      message(FATAL_ERROR "BUILD_SHARED_LIBS: ${program} loads no libbpde_*.so:\n${last_output}")
    endif()
    if(program MATCHES "(app|bpde|libbpde_jobs\\.so|_core[^/]*\\.so)$" AND count LESS 7)
      message(FATAL_ERROR "BUILD_SHARED_LIBS: ${program} loads only ${count} libbpde_*.so:\n${last_output}")
    endif()
  endif()
  # Each RUNPATH entry is relative to the file ($ORIGIN) or inside the prefix: nothing points back
  # into the build tree that was installed.
  run(${READELF} -d ${program})
  if(last_output MATCHES "\\(R(UN)?PATH\\)[^[]*\\[([^]]*)\\]")
    string(REPLACE ":" ";" entries "${CMAKE_MATCH_2}")
    foreach(e ${entries})
      string(FIND "${e}" "${prefix}/" in_prefix)
      if(NOT e MATCHES "^\\$ORIGIN" AND NOT in_prefix EQUAL 0)
        message(FATAL_ERROR "${program} has the RUNPATH entry ${e} outside the prefix (${prefix})")
      endif()
    endforeach()
  endif()
endforeach()
if(SHARED)
  set(kind "shared libraries loaded from the prefix")
else()
  set(kind "static")
endif()
if(PYTHON)
  set(kind "${kind}; the Python module imported from ${PYTHON_SITE}")
endif()
message(STATUS "package test (${kind}): installed, consumer built from README snippets (${names}) and run")
