# The installed library as a user gets it: `cmake --install` into a fresh prefix, the example
# program of examples/cpp_api configured with only find_package(bimrock) and built against it,
# then run on the pull-out example, whose collapse load is known in closed form: P = 2C = 40 kN
# of the stage's 60 kN, a load factor of 2/3 (examples/pull_out/README.md).
#   cmake -DBINARY_DIR=<build tree> -DSOURCE_DIR=<source tree> -DWORK_DIR=<scratch> -P cpp_api.cmake
foreach(var BINARY_DIR SOURCE_DIR WORK_DIR)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "give -D${var}=...")
  endif()
endforeach()

function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT code EQUAL 0)
    message(FATAL_ERROR "${ARGN}\nfailed (${code}):\n${out}\n${err}")
  endif()
  set(output "${out}" PARENT_SCOPE)
endfunction()

file(REMOVE_RECURSE ${WORK_DIR})
set(prefix ${WORK_DIR}/prefix)
run(${CMAKE_COMMAND} --install ${BINARY_DIR} --prefix ${prefix})
foreach(file include/bimrock/io/case_reader.hpp lib/libbimrock_io.a
        lib/cmake/bimrock/bimrockConfig.cmake lib/cmake/bimrock/bimrockTargets.cmake)
  if(NOT EXISTS ${prefix}/${file})
    message(FATAL_ERROR "not installed: ${file}")
  endif()
endforeach()
# The source tree's headers must not be what the example finds: it sees the prefix only.
run(${CMAKE_COMMAND} -S ${SOURCE_DIR}/examples/cpp_api -B ${WORK_DIR}/build
    -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_BUILD_TYPE=Debug)
run(${CMAKE_COMMAND} --build ${WORK_DIR}/build)
file(READ ${WORK_DIR}/build/CMakeFiles/pull_out.dir/flags.make flags)
if(flags MATCHES "${SOURCE_DIR}/src")
  message(FATAL_ERROR "the example was compiled with the source tree's headers:\n${flags}")
endif()
run(${WORK_DIR}/build/pull_out ${SOURCE_DIR}/examples/pull_out/case.yaml)
message(STATUS "${output}")
if(NOT output MATCHES "collapse in stage 'pull' between load factors ([0-9.]+) and ([0-9.]+)")
  message(FATAL_ERROR "no collapse of the pull stage reported:\n${output}")
endif()
set(carried ${CMAKE_MATCH_1})
set(failed ${CMAKE_MATCH_2})
if(carried GREATER 0.66667 OR failed LESS 0.66666 OR failed GREATER 0.7)
  message(FATAL_ERROR "collapse bracket [${carried}, ${failed}] misses 2/3 (P = 40 kN of 60 kN)")
endif()
