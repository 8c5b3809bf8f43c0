# `cmake --install build [--prefix P]`: the library (api/), its headers, the shaders it reads at
# run time, the `eikon` command line, and the CMake package (find_package(Eikon) ->
# Eikon::eikon). tests/scripts/test_install.sh builds examples/cpp against it.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)
set(EIKON_OPENVDB_MODULE_DIR /usr/lib/x86_64-linux-gnu/cmake/OpenVDB)
install(TARGETS eikon_api EXPORT EikonTargets
    LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
    INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(TARGETS eikon RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/include/eikon DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/shaders/ DESTINATION ${CMAKE_INSTALL_DATADIR}/eikon/shaders
    PATTERN test EXCLUDE)
install(EXPORT EikonTargets NAMESPACE Eikon:: DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/Eikon)
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/EikonConfig.cmake.in
    ${CMAKE_BINARY_DIR}/EikonConfig.cmake INSTALL_DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/Eikon)
write_basic_package_version_file(${CMAKE_BINARY_DIR}/EikonConfigVersion.cmake
    COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_BINARY_DIR}/EikonConfig.cmake ${CMAKE_BINARY_DIR}/EikonConfigVersion.cmake
    DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/Eikon)
