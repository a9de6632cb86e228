# ptz_protocol(): everything one device protocol adds to the build, declared once (cmake/protocols.cmake).
#
#   ptz_protocol(<name>
#     CORE <sources>              its codec and DeviceProtocol: into ptz_core (plain C++17, no ROS include)
#     PLUGIN <sources>            its backend plugin: into ptz_backend_plugins (a <class> in backend_plugins.xml)
#     EMULATOR <sources>          its emulated device: into the ptz_emulators library
#     PROGRAM <program> <source>  the emulator program that runs it on a real port (installed)
#     HARNESS <function> <sources>
#                                 its harnesses (test/harness/): into ptz_harness, which the contract fixtures and the
#                                 benchmarks share; <function>() returns the protocol's rows of ptz_bench's device
#                                 table (std::vector<HarnessEntry>), allHarnesses() every protocol's
#     TESTS <sources>             its gtests and its contract fixture: into test_core
#     FUZZ <target> <sources>     libFuzzer harness test/fuzz/fuzz_<target>.cpp over these core sources, seeded from
#                                 test/fuzz/corpus/<target>/ (built with -DPTZ_FUZZ=ON only)
#     FUZZ_LIBS <libraries>       what the harness links beside nlohmann_json
#     ROSTESTS <files>            rostests of the node against PROGRAM
#   )
#
# The lists fill global properties that CMakeLists.txt turns into the libraries (ptz_harness's registry too), test_core
# and the rostests; the install rules and scripts/test's expected results follow from them.

function(ptz_protocol name)
  cmake_parse_arguments(PARSE_ARGV 1 ARG "" "" "CORE;PLUGIN;EMULATOR;PROGRAM;HARNESS;TESTS;FUZZ;FUZZ_LIBS;ROSTESTS")
  if(ARG_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "ptz_protocol(${name}): unknown arguments ${ARG_UNPARSED_ARGUMENTS}")
  endif()
  if(PTZ_FUZZ)
    if(ARG_FUZZ)
      list(POP_FRONT ARG_FUZZ fuzz_target)
      ptz_add_fuzzer(${fuzz_target} ${ARG_FUZZ})
      if(ARG_FUZZ_LIBS)
        target_link_libraries(fuzz_${fuzz_target} PRIVATE ${ARG_FUZZ_LIBS})
      endif()
    endif()
    return()
  endif()
  set_property(GLOBAL APPEND PROPERTY PTZ_PROTOCOLS ${name})
  set_property(GLOBAL APPEND PROPERTY PTZ_CORE_SOURCES ${ARG_CORE})
  set_property(GLOBAL APPEND PROPERTY PTZ_PLUGIN_SOURCES ${ARG_PLUGIN})
  set_property(GLOBAL APPEND PROPERTY PTZ_EMULATOR_SOURCES ${ARG_EMULATOR})
  # Its emulator's classify() file (small) stays out of the unity batches, which stay as they were.
  foreach(source ${ARG_EMULATOR})
    if(source MATCHES "_classify\\.cpp$")
      set_source_files_properties(${source} PROPERTIES SKIP_UNITY_BUILD_INCLUSION ON)
    endif()
  endforeach()
  set_property(GLOBAL APPEND PROPERTY PTZ_TEST_SOURCES ${ARG_TESTS})
  if(ARG_HARNESS)
    list(POP_FRONT ARG_HARNESS harness_function)
    set_property(GLOBAL APPEND PROPERTY PTZ_HARNESS_FUNCTIONS ${harness_function})
    set_property(GLOBAL APPEND PROPERTY PTZ_HARNESS_SOURCES ${ARG_HARNESS})
  endif()
  set(program "")
  if(ARG_PROGRAM)
    list(LENGTH ARG_PROGRAM count)
    if(NOT count EQUAL 2)
      message(FATAL_ERROR "ptz_protocol(${name}): PROGRAM takes a name and one source")
    endif()
    list(GET ARG_PROGRAM 0 program)
    list(GET ARG_PROGRAM 1 program_source)
    add_executable(${program} ${program_source})
    target_link_libraries(${program} ptz_emulators)
    set_property(GLOBAL APPEND PROPERTY PTZ_EMULATOR_PROGRAMS ${program})
  endif()
  # file|program pairs: CMakeLists.txt adds them once rostest is found.
  foreach(rostest ${ARG_ROSTESTS})
    set_property(GLOBAL APPEND PROPERTY PTZ_PROTOCOL_ROSTESTS "${rostest}|${program}")
  endforeach()
endfunction()

# ptz_harness_library(): ptz_harness, the harnesses (test/harness/) of every protocol above: its HARNESS sources, on
# ptz_emulators, and allHarnesses(), which calls each protocol's HARNESS function (generated from
# test/harness/harness_registry.cpp.in). The contract fixtures (test_core) and the benchmarks link it, never the node.
function(ptz_harness_library)
  get_property(functions GLOBAL PROPERTY PTZ_HARNESS_FUNCTIONS)
  get_property(sources GLOBAL PROPERTY PTZ_HARNESS_SOURCES)
  set(PTZ_HARNESS_DECLARATIONS "")
  foreach(function ${functions})
    string(APPEND PTZ_HARNESS_DECLARATIONS "std::vector<HarnessEntry> ${function}();\n")
  endforeach()
  string(REPLACE ";" ", " PTZ_HARNESS_CALLS "${functions}")
  configure_file(test/harness/harness_registry.cpp.in harness_registry.cpp @ONLY)
  add_library(ptz_harness STATIC test/harness/device_harness.cpp ${sources}
    ${CMAKE_CURRENT_BINARY_DIR}/harness_registry.cpp)
  target_include_directories(ptz_harness PUBLIC test)
  target_link_libraries(ptz_harness PUBLIC ptz_emulators)
endfunction()

# ptz_add_fuzzer(<target> <sources>): fuzz_<target> from test/fuzz/fuzz_<target>.cpp, with ASan and UBSan (clang).
function(ptz_add_fuzzer target)
  add_executable(fuzz_${target} test/fuzz/fuzz_${target}.cpp ${ARGN})
  target_include_directories(fuzz_${target} PRIVATE include)
  target_link_libraries(fuzz_${target} PRIVATE nlohmann_json::nlohmann_json)
  target_compile_options(fuzz_${target} PRIVATE -g -O1 -fsanitize=fuzzer,address,undefined
    -fno-sanitize-recover=all)
  target_link_options(fuzz_${target} PRIVATE -fsanitize=fuzzer,address,undefined)
endfunction()
