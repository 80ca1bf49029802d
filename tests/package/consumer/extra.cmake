# Appended by tests/package/run_consumer.cmake after the README's CMake snippet (the consumer's
# CMakeLists.txt): a second program on one component target, and the version file's verdicts.
target_include_directories(app PRIVATE ${CMAKE_CURRENT_SOURCE_DIR})  # the consumer's own core/
add_executable(nets_only nets_only.cpp)
target_link_libraries(nets_only PRIVATE bezierpde::core)
get_target_property(bpde_features bezierpde::core INTERFACE_COMPILE_FEATURES)
if(NOT bpde_features MATCHES "cxx_std_20")
  message(FATAL_ERROR "bezierpde::core does not pass C++20 on: ${bpde_features}")
endif()
foreach(wrong 0.1 0.3 1.0)
  find_package(bezierpde ${wrong} CONFIG QUIET)
  if(bezierpde_FOUND)
    message(FATAL_ERROR "find_package(bezierpde ${wrong}) accepted version ${bezierpde_VERSION}")
  endif()
endforeach()
