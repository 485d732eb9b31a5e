# Runs a test campaign once without MPI and once under `mpirun -np PROCESSES`, and requires
# samples.csv, summary.csv, sensitivity.csv, provenance.json and (for raw-data lines with a bootstrap) data_uncertainty.csv and
# the line comparisons' comparisons.csv and letters.csv, and an audit's audit.csv, to be
# identical byte for byte, and results.h5 value for value (its analyses and raw-data fits are
# computed by all processes together; the command line stored in it names another --out, so its
# bytes differ), when /usr/bin/python3 has h5py: results must not depend on the number of
# processes.
# Variables: CLI, MPIEXEC, PROCESSES, CAMPAIGN, WORK, COMPARE (tools/bench/compare_results_h5.py);
# SAMPLES (optional) overrides the campaign's samples per line.
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")
set(sample_options)
if(DEFINED SAMPLES)
  set(sample_options --samples ${SAMPLES})
endif()
execute_process(COMMAND "${CLI}" run "${CAMPAIGN}" --quiet --formats csv,hdf5 ${sample_options} --out "${WORK}/serial"
                RESULT_VARIABLE serial_result ERROR_VARIABLE serial_error)
if(NOT serial_result EQUAL 0)
  message(FATAL_ERROR "serial run failed (${serial_result}): ${serial_error}")
endif()
execute_process(COMMAND "${MPIEXEC}" -np ${PROCESSES} --oversubscribe "${CLI}" run "${CAMPAIGN}" --quiet --formats csv,hdf5
                        ${sample_options} --out "${WORK}/mpi"
                RESULT_VARIABLE mpi_result ERROR_VARIABLE mpi_error)
if(NOT mpi_result EQUAL 0)
  message(FATAL_ERROR "run under mpirun -np ${PROCESSES} failed (${mpi_result}): ${mpi_error}")
endif()
set(compared samples.csv summary.csv sensitivity.csv provenance.json)
foreach(optional data_uncertainty.csv comparisons.csv letters.csv audit.csv)
  if(EXISTS "${WORK}/serial/${optional}")
    list(APPEND compared ${optional})
  endif()
endforeach()
foreach(name ${compared})
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
