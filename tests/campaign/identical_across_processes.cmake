# Runs the small test campaign once without MPI and once under `mpirun -np PROCESSES`, and
# requires samples.csv and summary.csv to be identical byte for byte, and results.h5 value for
# value (its analyses are computed by all processes together; HDF5 stores times, so its bytes
# differ), when /usr/bin/python3 has h5py: results must not depend on the number of processes.
# Variables: CLI, MPIEXEC, PROCESSES, CAMPAIGN, WORK, COMPARE (tools/compare_results_h5.py).
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")
execute_process(COMMAND "${CLI}" run "${CAMPAIGN}" --quiet --formats csv,hdf5 --out "${WORK}/serial"
                RESULT_VARIABLE serial_result ERROR_VARIABLE serial_error)
if(NOT serial_result EQUAL 0)
  message(FATAL_ERROR "serial run failed (${serial_result}): ${serial_error}")
endif()
execute_process(COMMAND "${MPIEXEC}" -np ${PROCESSES} --oversubscribe "${CLI}" run "${CAMPAIGN}" --quiet --formats csv,hdf5
                        --out "${WORK}/mpi"
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
execute_process(COMMAND /usr/bin/python3 -c "import h5py, numpy" RESULT_VARIABLE no_h5py OUTPUT_QUIET ERROR_QUIET)
if(no_h5py EQUAL 0)
  execute_process(COMMAND /usr/bin/python3 "${COMPARE}" "${WORK}/serial/results.h5" "${WORK}/mpi/results.h5"
                  RESULT_VARIABLE differs OUTPUT_VARIABLE comparison)
  if(NOT differs EQUAL 0)
    message(FATAL_ERROR "results.h5 differs between the serial run and mpirun -np ${PROCESSES}: ${comparison}(kept in ${WORK})")
  endif()
else()
  message(STATUS "results.h5 not compared: /usr/bin/python3 with h5py and numpy is not available")
endif()
file(REMOVE_RECURSE "${WORK}")
