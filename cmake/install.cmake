# Installed like a tool (`cmake --install`, and the Debian package `cpack` builds): the program,
# its OpenImageIO module in lib/radiant (found relative to the program, so any prefix works),
# the man page and bash/zsh completions generated from the program's own --help, and the
# bundled scenes.
install(TARGETS radiant RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(TARGETS radiant_oiio LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}/radiant)
install(DIRECTORY assets/ DESTINATION ${CMAKE_INSTALL_DATADIR}/radiant/assets)

# The sanitizer and fuzzer builds run no tool at build time (their leak reports would fail it).
if(NOT RADIANT_SANITIZE AND NOT RADIANT_FUZZ)
  find_package(Python3 REQUIRED COMPONENTS Interpreter)
  set(RADIANT_MANUAL_DIR ${CMAKE_BINARY_DIR}/manual)
  add_custom_command(
    OUTPUT ${RADIANT_MANUAL_DIR}/radiant.1 ${RADIANT_MANUAL_DIR}/radiant.bash ${RADIANT_MANUAL_DIR}/_radiant
    COMMAND Python3::Interpreter ${PROJECT_SOURCE_DIR}/packaging/make_manual.py $<TARGET_FILE:radiant> ${RADIANT_MANUAL_DIR}
    DEPENDS radiant ${PROJECT_SOURCE_DIR}/packaging/make_manual.py
    COMMENT "Generating the man page and completions from radiant --help")
  add_custom_target(radiant_manual ALL DEPENDS ${RADIANT_MANUAL_DIR}/radiant.1)
  install(FILES ${RADIANT_MANUAL_DIR}/radiant.1 DESTINATION ${CMAKE_INSTALL_MANDIR}/man1)
  install(FILES ${RADIANT_MANUAL_DIR}/radiant.bash DESTINATION ${CMAKE_INSTALL_DATADIR}/bash-completion/completions
          RENAME radiant)
  install(FILES ${RADIANT_MANUAL_DIR}/_radiant DESTINATION ${CMAKE_INSTALL_DATADIR}/zsh/vendor-completions)
endif()

# `cpack` in the build folder: a .deb whose dependencies dpkg-shlibdeps reads from the Debian
# libraries radiant and its module link.
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME radiant)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "batch renderer for glTF 2.0, OBJ and .scene files (Whitted and path tracing)")
set(CPACK_PACKAGE_CONTACT "radiant developers <radiant@localhost>")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION graphics)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
include(CPack)
