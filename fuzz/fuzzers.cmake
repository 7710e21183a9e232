# Included by the top-level CMakeLists.txt: builds the fuzz targets of fuzz/ (their own project,
# with clang++) into bin/ with every build, and registers a short run of each as a test.
include(ExternalProject)
find_program(CLANGXX NAMES clang++ clang++-14 REQUIRED)
get_target_property(lcmtypes_include lcmtypes INTERFACE_INCLUDE_DIRECTORIES)

ExternalProject_Add(fuzzers
  SOURCE_DIR ${PROJECT_SOURCE_DIR}/fuzz
  BINARY_DIR ${CMAKE_BINARY_DIR}/fuzz
  CMAKE_ARGS -DCMAKE_CXX_COMPILER=${CLANGXX}
             -DLCMTYPES_INCLUDE_DIR=${lcmtypes_include}
             -DPARAMS_GENERATED_DIR=${CMAKE_BINARY_DIR}/sim/params
             -DCMAKE_RUNTIME_OUTPUT_DIRECTORY=${CMAKE_RUNTIME_OUTPUT_DIRECTORY}
  # The sources are outside ExternalProject's view: the fuzz project's own make decides what is
  # out of date, in a second or less when nothing is.
  BUILD_ALWAYS ON
  INSTALL_COMMAND ""
  DEPENDS lcmtypes_gen params)

# 6 s per target from the generated seeds, in a fresh corpus each time; any crash, leak,
# sanitizer report or broken property fails the test.
file(GLOB fuzz_target_sources CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/fuzz/fuzz_*.cc)
foreach(source ${fuzz_target_sources})
  get_filename_component(target ${source} NAME_WE)
  add_test(NAME ${target}
           COMMAND bash ${PROJECT_SOURCE_DIR}/fuzz/run_fuzzers.sh --seconds 6
                   --bin-dir ${CMAKE_RUNTIME_OUTPUT_DIRECTORY} ${target})
  set_tests_properties(${target} PROPERTIES TIMEOUT 120 LABELS fuzz)
endforeach()
