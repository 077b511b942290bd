# Compiles the engine's prediction code as the engine is compiled and requires GCC's vectorizer to
# report the batched pair test's loop vectorized (physics/collision_batch.hpp).  A default flag
# once kept that loop scalar, with two unpredictable branches per pair, and no other test could
# see it: the results are the same bit for bit either way (docs/performance.md, "The pair test in
# vector registers, really").
# Arguments: CXX, FLAGS (a |-separated list), SOURCE.
string(REPLACE "|" ";" flags "${FLAGS}")
execute_process(COMMAND ${CXX} ${flags} -fopt-info-vec-all -c ${SOURCE} -o /dev/null
                RESULT_VARIABLE status ERROR_VARIABLE report OUTPUT_VARIABLE output)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "compiling ${SOURCE} failed:\n${report}")
endif()
if(NOT report MATCHES "collision_batch\\.hpp:[0-9]+:[0-9]+: optimized: loop vectorized")
  string(REGEX MATCHALL "collision_batch\\.hpp:[^\n]*missed: not vectorized[^\n]*" missed "${report}")
  message(FATAL_ERROR "the batched pair test was not vectorized; GCC said:\n${missed}")
endif()
message(STATUS "the batched pair test is vectorized")
