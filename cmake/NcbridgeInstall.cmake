# `cmake --install` and `cpack -G DEB` (docs/install.md):
#   bin/                         ncbridge and the services (ncbridge up starts those beside it)
#   share/ncbridge/              iso14649.exp (when the build has it), cyclonedds/*.xml, examples/
#   share/man/man1/ncbridge.1    made from the built command's --help texts
#   share/bash-completion/completions/ncbridge
#   share/doc/ncbridge/          README.md and docs/
#   include/ncbridge/, lib/      the stages' headers and static libraries, and
#   lib/cmake/ncbridge/          a package config: find_package(ncbridge) gives ncbridge::common,
#                                ncbridge::interpreter, ncbridge::cc1_builder, ...
# Components: runtime, development, and iso14649_schema (the ISO text, which no licence lets us
# redistribute: installed by `cmake --install`, left out of the .deb).
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(NCBRIDGE_ISO14649_SCHEMA_SOURCE "${NCBRIDGE_SHARED_DIR}/reference/iso14649/combined_schema_iso14649_only.exp"
    CACHE FILEPATH "The ISO 14649 EXPRESS schema installed as share/ncbridge/iso14649.exp (when it exists)")

# ---- executables
set(_ncbridge_programs ncbridge ncbridge-interpreter ncbridge-cc1-builder ncbridge-feature-recognizer ncbridge-step-writer)
foreach(program IN LISTS _ncbridge_programs)
  if(TARGET ${program})
    install(TARGETS ${program} RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} COMPONENT runtime)
  endif()
endforeach()

# ---- data
if(EXISTS "${NCBRIDGE_ISO14649_SCHEMA_SOURCE}")
  install(FILES "${NCBRIDGE_ISO14649_SCHEMA_SOURCE}" DESTINATION ${CMAKE_INSTALL_DATADIR}/ncbridge
          RENAME iso14649.exp COMPONENT iso14649_schema)
else()
  message(STATUS "ncbridge install: no ISO 14649 schema at ${NCBRIDGE_ISO14649_SCHEMA_SOURCE}; "
                 "an installed `ncbridge check` will need --schema or NCBRIDGE_ISO14649_SCHEMA")
endif()
install(DIRECTORY ${PROJECT_SOURCE_DIR}/deploy/cyclonedds/ DESTINATION ${CMAKE_INSTALL_DATADIR}/ncbridge/cyclonedds
        COMPONENT runtime FILES_MATCHING PATTERN "*.xml")
install(DIRECTORY ${PROJECT_SOURCE_DIR}/examples/ DESTINATION ${CMAKE_INSTALL_DATADIR}/ncbridge/examples COMPONENT runtime)
install(FILES ${PROJECT_SOURCE_DIR}/README.md DESTINATION ${CMAKE_INSTALL_DOCDIR} COMPONENT runtime)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/docs/ DESTINATION ${CMAKE_INSTALL_DOCDIR}/docs COMPONENT runtime)
install(FILES ${PROJECT_SOURCE_DIR}/completions/ncbridge DESTINATION ${CMAKE_INSTALL_DATADIR}/bash-completion/completions
        COMPONENT runtime)

# ---- man page: the hand-written parts (man/ncbridge.1.in) and each command's --help
if(TARGET ncbridge AND NOT NCBRIDGE_FUZZ)  # the fuzz build's command is instrumented for libFuzzer
  set(_ncbridge_man ${CMAKE_BINARY_DIR}/man/ncbridge.1)
  add_custom_command(OUTPUT ${_ncbridge_man}
    COMMAND ${CMAKE_COMMAND} -DNCBRIDGE=$<TARGET_FILE:ncbridge> -DTEMPLATE=${PROJECT_SOURCE_DIR}/man/ncbridge.1.in
            -DOUTPUT=${_ncbridge_man} -DVERSION=${PROJECT_VERSION} -P ${PROJECT_SOURCE_DIR}/cmake/NcbridgeManPage.cmake
    DEPENDS ncbridge ${PROJECT_SOURCE_DIR}/man/ncbridge.1.in ${PROJECT_SOURCE_DIR}/cmake/NcbridgeManPage.cmake
    COMMENT "man page ncbridge.1 from the commands' --help")
  add_custom_target(ncbridge_man_page ALL DEPENDS ${_ncbridge_man})
  install(FILES ${_ncbridge_man} DESTINATION ${CMAKE_INSTALL_MANDIR}/man1 COMPONENT runtime)
endif()

# ---- libraries, headers and the package config
# The stages' libraries as ncbridge::<name>; their include directories are the source tree's in
# the build and include/ once installed.
set(_ncbridge_libraries common stepnc_model interpreter cc1_builder feature_recognizer step_writer part_reader)
set(_ncbridge_exported ncbridge_warnings)
foreach(name IN LISTS _ncbridge_libraries)
  set(target ncbridge_${name})
  if(NOT TARGET ${target})
    continue()
  endif()
  get_target_property(dirs ${target} INTERFACE_INCLUDE_DIRECTORIES)
  set(wrapped)
  foreach(dir IN LISTS dirs)
    if(dir MATCHES "^\\$<")
      list(APPEND wrapped "${dir}")
    else()
      list(APPEND wrapped "$<BUILD_INTERFACE:${dir}>")
      install(DIRECTORY ${dir}/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR} COMPONENT development)
    endif()
  endforeach()
  list(APPEND wrapped "$<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>")
  set_target_properties(${target} PROPERTIES INTERFACE_INCLUDE_DIRECTORIES "${wrapped}" EXPORT_NAME ${name})
  list(APPEND _ncbridge_exported ${target})
endforeach()
install(TARGETS ${_ncbridge_exported} EXPORT ncbridgeTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT development
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT development)
install(EXPORT ncbridgeTargets NAMESPACE ncbridge:: DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/ncbridge
        COMPONENT development)
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/ncbridgeConfig.cmake.in
  ${CMAKE_BINARY_DIR}/cmake/ncbridgeConfig.cmake INSTALL_DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/ncbridge)
write_basic_package_version_file(${CMAKE_BINARY_DIR}/cmake/ncbridgeConfigVersion.cmake COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_BINARY_DIR}/cmake/ncbridgeConfig.cmake ${CMAKE_BINARY_DIR}/cmake/ncbridgeConfigVersion.cmake
        DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/ncbridge COMPONENT development)

# ---- cpack -G DEB: runtime and development in one package, without the ISO schema
set(CPACK_PACKAGE_NAME ncbridge)
set(CPACK_PACKAGE_VENDOR "ncbridge")
set(CPACK_PACKAGE_CONTACT "ncbridge developers <ncbridge@localhost>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "${PROJECT_DESCRIPTION}")
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
# Only these components go into the package (the schema's does not).
set(CPACK_INSTALL_CMAKE_PROJECTS "${CMAKE_BINARY_DIR};ncbridge;runtime;/;${CMAKE_BINARY_DIR};ncbridge;development;/")
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)  # the run-time libraries' packages, from dpkg-shlibdeps
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "bash-completion")
set(CPACK_DEBIAN_PACKAGE_SUGGESTS "libyaml-cpp-dev, nlohmann-json3-dev, libpolyclipping-dev, linuxcnc-uspace")
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_STRIP_FILES ON)
set(CPACK_DEBIAN_PACKAGE_DESCRIPTION "Reads G-code (RS274/NGC, Fanuc, Mach3/4, Siemens 840D, Heidenhain) and \
writes ISO 14649 CC1/CC2 files; checks and compares Part 21 files; runs the stages as DDS services. \
The ISO 14649 EXPRESS schema is not included (its text is ISO's): ncbridge check needs --schema, \
NCBRIDGE_ISO14649_SCHEMA or the file at /usr/share/ncbridge/iso14649.exp.")
include(CPack)
