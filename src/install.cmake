# Installing growthuq: the library, its public headers (include/growthuq/, the API a program
# calls; the headers in src/ are internal and are not installed), the command-line program, the
# licence, and a CMake package, so that another project writes
#   find_package(growthuq CONFIG REQUIRED)
#   target_link_libraries(app PRIVATE growthuq::growthuq)
# (tests/install/ builds such a project against an installed copy).
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(GROWTHUQ_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/growthuq)

install(TARGETS growthuq EXPORT growthuqTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
        INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/include/growthuq DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
        FILES_MATCHING PATTERN "*.hpp")
install(TARGETS growthuq_cli RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
if(EXISTS ${PROJECT_SOURCE_DIR}/LICENSE)
  install(FILES ${PROJECT_SOURCE_DIR}/LICENSE DESTINATION ${CMAKE_INSTALL_DOCDIR})
endif()

install(EXPORT growthuqTargets NAMESPACE growthuq:: DESTINATION ${GROWTHUQ_INSTALL_CMAKEDIR})
# A static library takes its private dependencies (GSL, SUNDIALS, HDF5, MPI) into every program
# that links it, so the package must find them too; a shared one needs only Eigen, which the
# public headers include.
get_target_property(GROWTHUQ_LIBRARY_TYPE growthuq TYPE)
configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/growthuqConfig.cmake.in
                              ${PROJECT_BINARY_DIR}/growthuqConfig.cmake
                              INSTALL_DESTINATION ${GROWTHUQ_INSTALL_CMAKEDIR})
# 0.y: a minor version may change the API, so only the same major.minor is compatible.
write_basic_package_version_file(${PROJECT_BINARY_DIR}/growthuqConfigVersion.cmake
                                 COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/growthuqConfig.cmake ${PROJECT_BINARY_DIR}/growthuqConfigVersion.cmake
        DESTINATION ${GROWTHUQ_INSTALL_CMAKEDIR})
