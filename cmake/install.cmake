# Install and export rules (doc/building.md, "Using picdem from another project"): `cmake --install`
# puts the module libraries, their public headers, the picdem executable and a CMake package
# (find_package(picdem), targets picdem::core, picdem::geometry, ...) under the prefix. GoogleTest
# is not needed by the package. Included at the end of the top-level CMakeLists.txt.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)
set(_picdem_config_dir ${CMAKE_INSTALL_LIBDIR}/cmake/picdem)

set(_picdem_libraries)
foreach(m core grid particles fluid dem io geometry coupling run)
  if(TARGET picdem_${m})
    list(APPEND _picdem_libraries picdem_${m})
  endif()
endforeach()
foreach(t ${_picdem_libraries})
  # Each module's include folder holds only public headers (private ones sit in src/); installed,
  # they all land in <prefix>/include/picdem/<module>/.
  get_target_property(_dirs ${t} INTERFACE_INCLUDE_DIRECTORIES)
  set(_build_dirs)
  foreach(d ${_dirs})
    list(APPEND _build_dirs "$<BUILD_INTERFACE:${d}>")
    install(DIRECTORY ${d}/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
  endforeach()
  set_target_properties(${t} PROPERTIES INTERFACE_INCLUDE_DIRECTORIES "${_build_dirs}")
  target_include_directories(${t} INTERFACE $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
endforeach()
# picdem_core -> picdem::core; the wrappers of Trilinos and HDF5 go along (static libraries carry
# their private dependencies to the consumer's link).
set(_picdem_exported ${_picdem_libraries} picdem_teuchos picdem_trilinos picdem_hdf5)
foreach(t ${_picdem_exported})
  string(REPLACE "picdem_" "" _name ${t})
  set_target_properties(${t} PROPERTIES EXPORT_NAME ${_name})
endforeach()
install(TARGETS ${_picdem_exported} EXPORT picdemTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR} LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
if(TARGET picdem)
  install(TARGETS picdem RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
endif()
install(EXPORT picdemTargets NAMESPACE picdem:: DESTINATION ${_picdem_config_dir})
configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/picdemConfig.cmake.in
                              ${CMAKE_CURRENT_BINARY_DIR}/picdemConfig.cmake
                              INSTALL_DESTINATION ${_picdem_config_dir})
write_basic_package_version_file(${CMAKE_CURRENT_BINARY_DIR}/picdemConfigVersion.cmake
                                 COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/picdemConfig.cmake
              ${CMAKE_CURRENT_BINARY_DIR}/picdemConfigVersion.cmake
        DESTINATION ${_picdem_config_dir})
