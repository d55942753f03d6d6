# The one way to declare a library, a test and a benchmark in coinspect.

# Flags shared by every target of the project (never by third-party code).
add_library(coinspect_build_flags INTERFACE)
target_compile_options(coinspect_build_flags INTERFACE -Wall -Wextra -Wpedantic)
if(COINSPECT_SANITIZE)
  # -O1 -g1 (line tables only) after the build type's flags: ASan's recommended level, and
  # compiling is the sanitizer build's largest cost in CI (doc/benchmarks.md, "CI time").
  target_compile_options(coinspect_build_flags INTERFACE
    -fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined -O1 -g1)
  target_link_options(coinspect_build_flags INTERFACE -fsanitize=address,undefined)
endif()

# Where tests find the repository and the read-only reference data beside it (../shared).
set(COINSPECT_SHARED_DIR "${PROJECT_SOURCE_DIR}/../shared" CACHE PATH
    "Folder holding design/ and data/ (reference data, never copied into the repository)")

# coinspect_add_library(<name> [SOURCES ...] [DEPS ...] [PRIVATE_DEPS ...] [TESTS ...]
#                       [TEST_DEPS ...])
#   libs/<name>/include/coinspect/<name>/*.h are its public headers; it is exported as
#   coinspect::<name>. Without SOURCES it builds src/*.cpp of its folder, without TESTS each
#   tests/*_test.cpp becomes a gtest executable (test_<name>_<file>) linked to the library and to
#   TEST_DEPS. Globbing lets each concept live in its own file without editing CMake.
function(coinspect_add_library name)
  cmake_parse_arguments(ARG "" "" "SOURCES;DEPS;PRIVATE_DEPS;TESTS;TEST_DEPS" ${ARGN})
  if(NOT ARG_SOURCES)
    file(GLOB ARG_SOURCES CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/src/*.cpp)
  endif()
  if(NOT ARG_TESTS)
    file(GLOB ARG_TESTS CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/tests/*_test.cpp)
  endif()
  add_library(coinspect_${name} ${ARG_SOURCES})
  add_library(coinspect::${name} ALIAS coinspect_${name})
  set_target_properties(coinspect_${name} PROPERTIES OUTPUT_NAME coinspect_${name}
                                                     POSITION_INDEPENDENT_CODE ON)
  target_include_directories(coinspect_${name} PUBLIC
    $<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}/include>)
  target_link_libraries(coinspect_${name} PUBLIC ${ARG_DEPS} PRIVATE ${ARG_PRIVATE_DEPS}
                                                 coinspect_build_flags)
  if(COINSPECT_BUILD_TESTS)
    foreach(test_source IN LISTS ARG_TESTS)
      get_filename_component(test_name ${test_source} NAME_WE)
      coinspect_add_test(${name}_${test_name} SOURCES ${test_source}
                         DEPS coinspect::${name} ${ARG_TEST_DEPS})
    endforeach()
  endif()
endfunction()

# coinspect_add_test(<name> SOURCES ... [DEPS ...]) : one gtest executable, each TEST a ctest.
function(coinspect_add_test name)
  cmake_parse_arguments(ARG "" "" "SOURCES;DEPS" ${ARGN})
  add_executable(test_${name} ${ARG_SOURCES})
  target_link_libraries(test_${name} PRIVATE ${ARG_DEPS} coinspect::testing GTest::gtest_main
                                             coinspect_build_flags)
  set_target_properties(test_${name} PROPERTIES RUNTIME_OUTPUT_DIRECTORY
                                                ${PROJECT_BINARY_DIR}/tests)
  gtest_discover_tests(test_${name} DISCOVERY_MODE PRE_TEST DISCOVERY_TIMEOUT 60
                       WORKING_DIRECTORY ${PROJECT_BINARY_DIR}
                       PROPERTIES LABELS ${name})
endfunction()

# coinspect_add_benchmark(<name> SOURCES ... [DEPS ...]) : a Google Benchmark executable.
function(coinspect_add_benchmark name)
  cmake_parse_arguments(ARG "" "" "SOURCES;DEPS" ${ARGN})
  add_executable(bench_${name} ${ARG_SOURCES})
  target_link_libraries(bench_${name} PRIVATE ${ARG_DEPS} benchmark::benchmark
                                              coinspect_build_flags)
  target_compile_definitions(bench_${name} PRIVATE
    COINSPECT_SHARED_DIR="${COINSPECT_SHARED_DIR}")
endfunction()
