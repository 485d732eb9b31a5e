# Runs `growthuq tradeoff` on the small test campaign once without MPI and once under
# `mpirun -np PROCESSES`, and requires the same tables apart from the seconds column (wall
# times differ; every statistic must not). Variables: CLI, MPIEXEC, PROCESSES, CAMPAIGN, WORK.
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")
set(arguments tradeoff "${CAMPAIGN}" --samples-list 50,200,1000 --quiet)
execute_process(COMMAND "${CLI}" ${arguments} --out "${WORK}/serial.csv"
                RESULT_VARIABLE serial_result OUTPUT_QUIET ERROR_VARIABLE serial_error)
if(NOT serial_result EQUAL 0)
  message(FATAL_ERROR "serial tradeoff failed (${serial_result}): ${serial_error}")
endif()
execute_process(COMMAND "${MPIEXEC}" -np ${PROCESSES} --oversubscribe "${CLI}" ${arguments} --out "${WORK}/mpi.csv"
                RESULT_VARIABLE mpi_result OUTPUT_QUIET ERROR_VARIABLE mpi_error)
if(NOT mpi_result EQUAL 0)
  message(FATAL_ERROR "tradeoff under mpirun -np ${PROCESSES} failed (${mpi_result}): ${mpi_error}")
endif()
foreach(run serial mpi)
  file(STRINGS "${WORK}/${run}.csv" rows)
  list(LENGTH rows row_count)
  if(NOT row_count EQUAL 25)  # header + 3 counts x 2 lines x 4 quantities
    message(FATAL_ERROR "${run}.csv has ${row_count} lines, expected 25 (kept in ${WORK})")
  endif()
  list(TRANSFORM rows REPLACE "^([^,]*,[^,]*,)[^,]*" "\\1")  # blank the seconds column
  set(${run}_rows "${rows}")
endforeach()
if(NOT serial_rows STREQUAL mpi_rows)
  message(FATAL_ERROR "tradeoff tables differ between the serial run and mpirun -np ${PROCESSES} (kept in ${WORK})")
endif()
file(REMOVE_RECURSE "${WORK}")
