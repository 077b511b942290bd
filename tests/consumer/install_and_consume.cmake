# The installed-package test (ctest install.consumer): install this build into a temporary prefix,
# configure and build tests/consumer against it, run the consumer, and check that the installed
# granule command finds its plot scripts beside itself and through GRANULE_PYTHON_DIR.
# Arguments: -DBUILD_DIR=... -DSOURCE_DIR=... -DWORK_DIR=...
file(REMOVE_RECURSE ${WORK_DIR})
set(prefix ${WORK_DIR}/prefix)

function(step)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT code EQUAL 0)
    message(FATAL_ERROR "${ARGN}\nexit ${code}\n${out}\n${err}")
  endif()
  set(step_output "${out}" PARENT_SCOPE)
endfunction()

step(${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix})
step(${CMAKE_COMMAND} -S ${SOURCE_DIR}/tests/consumer -B ${WORK_DIR}/build -G Ninja -DCMAKE_BUILD_TYPE=Release
     -DCMAKE_PREFIX_PATH=${prefix})
step(${CMAKE_COMMAND} --build ${WORK_DIR}/build)
step(${WORK_DIR}/build/granule_consumer)
message(STATUS "consumer: ${step_output}")

# The installed binary runs its plot scripts from <prefix>/share/granule/python ...
foreach(file bin/granule share/granule/python/granule_plots/sweep.py include/granule/engine/simulation.hpp
        include/granule/version.hpp lib/cmake/granule/granuleConfig.cmake)
  if(NOT EXISTS ${prefix}/${file})
    message(FATAL_ERROR "not installed: ${file}")
  endif()
endforeach()
step(${prefix}/bin/granule run --out ${WORK_DIR}/run --set system.particles=200 --set run.until_collisions_per_particle=2)
step(${prefix}/bin/granule plot timeseries ${WORK_DIR}/run)
# ... and from GRANULE_PYTHON_DIR when it is set (a folder without them fails).
execute_process(COMMAND ${CMAKE_COMMAND} -E env GRANULE_PYTHON_DIR=${WORK_DIR}/nowhere ${prefix}/bin/granule plot timeseries
                        ${WORK_DIR}/run RESULT_VARIABLE code ERROR_VARIABLE err)
if(code EQUAL 0 OR NOT err MATCHES "nowhere")
  message(FATAL_ERROR "GRANULE_PYTHON_DIR is not where the scripts are looked for: exit ${code}: ${err}")
endif()
