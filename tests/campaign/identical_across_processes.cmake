# Runs the small test campaign once without MPI and once under `mpirun -np PROCESSES`, and
# requires samples.csv and summary.csv to be identical byte for byte (results must not depend
# on the number of processes). Variables: CLI, MPIEXEC, PROCESSES, CAMPAIGN, WORK.
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")
execute_process(COMMAND "${CLI}" run "${CAMPAIGN}" --quiet --out "${WORK}/serial"
                RESULT_VARIABLE serial_result ERROR_VARIABLE serial_error)
if(NOT serial_result EQUAL 0)
  message(FATAL_ERROR "serial run failed (${serial_result}): ${serial_error}")
endif()
execute_process(COMMAND "${MPIEXEC}" -np ${PROCESSES} --oversubscribe "${CLI}" run "${CAMPAIGN}" --quiet --out "${WORK}/mpi"
                RESULT_VARIABLE mpi_result ERROR_VARIABLE mpi_error)
if(NOT mpi_result EQUAL 0)
  message(FATAL_ERROR "run under mpirun -np ${PROCESSES} failed (${mpi_result}): ${mpi_error}")
endif()
foreach(name samples.csv summary.csv)
  execute_process(COMMAND "${CMAKE_COMMAND}" -E compare_files "${WORK}/serial/${name}" "${WORK}/mpi/${name}"
                  RESULT_VARIABLE differs)
  if(NOT differs EQUAL 0)
    message(FATAL_ERROR "${name} differs between the serial run and mpirun -np ${PROCESSES} (kept in ${WORK})")
  endif()
endforeach()
file(REMOVE_RECURSE "${WORK}")
