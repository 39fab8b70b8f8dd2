include(CMakePackageConfigHelpers)
install(EXPORT rbcstabTargets NAMESPACE rbcstab:: DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/rbcstab)
configure_package_config_file(cmake/rbcstabConfig.cmake.in ${CMAKE_CURRENT_BINARY_DIR}/rbcstabConfig.cmake
  INSTALL_DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/rbcstab)
write_basic_package_version_file(${CMAKE_CURRENT_BINARY_DIR}/rbcstabConfigVersion.cmake COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/rbcstabConfig.cmake ${CMAKE_CURRENT_BINARY_DIR}/rbcstabConfigVersion.cmake
  ${PROJECT_SOURCE_DIR}/cmake/RbcstabIpopt.cmake
  DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/rbcstab)
