# test_install: installs the build tree into a scratch prefix, checks that exactly the public
# headers were installed (every include/growthuq/ header, none of src/), then configures, builds
# and runs the outside project in project/ against that prefix with find_package(growthuq); it
# runs a small campaign in SCRATCH/campaign.
# Variables: BUILD_DIR (the growthuq build), SOURCE_DIR, SCRATCH (emptied), GENERATOR,
# CXX_COMPILER.
foreach(variable BUILD_DIR SOURCE_DIR SCRATCH GENERATOR CXX_COMPILER)
  if(NOT DEFINED ${variable})
    message(FATAL_ERROR "install_and_build.cmake needs -D${variable}=...")
  endif()
endforeach()

function(run what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "${what} failed (${status}):\n${out}\n${err}")
  endif()
  set(last_output "${out}" PARENT_SCOPE)
endfunction()

file(REMOVE_RECURSE ${SCRATCH})
set(prefix ${SCRATCH}/prefix)
run("installing" ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix})

# The installed headers are the public ones, no more and no fewer.
file(GLOB_RECURSE public RELATIVE ${SOURCE_DIR}/include ${SOURCE_DIR}/include/growthuq/*.hpp)
file(GLOB_RECURSE installed RELATIVE ${prefix}/include ${prefix}/include/*)
list(SORT public)
list(SORT installed)
if(NOT public STREQUAL installed)
  set(missing ${public})
  list(REMOVE_ITEM missing ${installed})
  set(extra ${installed})
  list(REMOVE_ITEM extra ${public})
  message(FATAL_ERROR "installed headers differ from include/growthuq/: missing [${missing}], extra [${extra}]")
endif()
list(LENGTH public count)
message(STATUS "${count} public headers installed")
foreach(file bin/growthuq lib/cmake/growthuq/growthuqConfig.cmake lib/cmake/growthuq/growthuqConfigVersion.cmake)
  if(NOT EXISTS ${prefix}/${file})
    message(FATAL_ERROR "not installed: ${file}")
  endif()
endforeach()

run("the installed CLI" ${prefix}/bin/growthuq --version)
message(STATUS "installed CLI: ${last_output}")

# CMAKE_FIND_USE_PACKAGE_REGISTRY off: the package must come from the prefix, nowhere else.
run("configuring the outside project" ${CMAKE_COMMAND} -S ${SOURCE_DIR}/tests/install/project -B ${SCRATCH}/build
    -G ${GENERATOR} -DCMAKE_CXX_COMPILER=${CXX_COMPILER} -DCMAKE_BUILD_TYPE=Release
    -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF)
run("building the outside project" ${CMAKE_COMMAND} --build ${SCRATCH}/build)
run("running the outside project" ${SCRATCH}/build/outside ${SCRATCH}/campaign)
message(STATUS "${last_output}")
