# `cmake --install BUILD [--prefix P]`: the C++ API (api/anisocert.hpp, docs/api.md) as the CMake
# package anisocert, for a mesher's own tests:
#   find_package(anisocert 0.1 REQUIRED)
#   target_link_libraries(my_tests PRIVATE anisocert::anisocert)
# Installed: the static library of every layer the API uses (the refiners and the CLI's internals
# are not part of it), their headers under include/anisocert/ with their project paths
# ("io/formats/registry.hpp"), the package files under lib/cmake/anisocert/, and the anisocert
# program. Each exported library is anisocert::<layer> (anisocert::io, ...); anisocert::anisocert
# is the API's and brings the others.
include(CMakePackageConfigHelpers)

set(anisocert_installed_layers numbers theory predicates geometry fields oracle io api)
set(anisocert_installed_libraries anisocert_numbers anisocert_intervals anisocert_theory anisocert_predicates
    anisocert_geometry anisocert_fields anisocert_oracle anisocert_io anisocert_api)
foreach(lib IN LISTS anisocert_installed_libraries)
  if(NOT lib STREQUAL "anisocert_api")
    string(REPLACE "anisocert_" "" name ${lib})
    set_target_properties(${lib} PROPERTIES EXPORT_NAME ${name})
  endif()
endforeach()

install(TARGETS ${anisocert_installed_libraries} EXPORT anisocertTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
foreach(layer IN LISTS anisocert_installed_layers)
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/${layer}/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/anisocert/${layer}
          FILES_MATCHING PATTERN "*.hpp")
endforeach()
install(TARGETS anisocert RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})

set(anisocert_package_dir ${CMAKE_INSTALL_LIBDIR}/cmake/anisocert)
install(EXPORT anisocertTargets NAMESPACE anisocert:: DESTINATION ${anisocert_package_dir})
configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/anisocertConfig.cmake.in
                              ${PROJECT_BINARY_DIR}/anisocertConfig.cmake INSTALL_DESTINATION ${anisocert_package_dir}
                              PATH_VARS CMAKE_INSTALL_BINDIR)
# 0.x: a minor version may change the API.
write_basic_package_version_file(${PROJECT_BINARY_DIR}/anisocertConfigVersion.cmake COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/anisocertConfig.cmake ${PROJECT_BINARY_DIR}/anisocertConfigVersion.cmake
              ${CMAKE_CURRENT_LIST_DIR}/anisocertArithmetic.cmake
        DESTINATION ${anisocert_package_dir})
