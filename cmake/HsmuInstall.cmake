# Install rules and the Debian package (docs/console.md, "Installing").
#   cmake --install build --prefix PREFIX   puts
#     PREFIX/bin/hsmu, PREFIX/bin/hsmu-cli (the Qt Core subcommands, started by hsmu),
#     PREFIX/bin/hsmu-console (the console, started by hsmu-cli), PREFIX/bin/hsmu-controller
#     PREFIX/share/hsmu/presets/*.json            (also embedded in both programs)
#     PREFIX/share/hsmu/translations/hsmu_*.qm    (also embedded in hsmu-cli, hsmu-console)
#     PREFIX/share/hsmu/opensees/hsmu_twin.tcl    (the OpenSees side of numerical twins)
#     PREFIX/share/applications/hsmu.desktop
#     PREFIX/share/icons/hicolor/scalable/apps/hsmu.svg
#     PREFIX/share/doc/hsmu/{README.md, *.md}
#     PREFIX/lib/python3/dist-packages/hsmu.cpython-*.so   (the Python module, python/)
#   cpack -G DEB (in build/) makes hsmu_<version>_<arch>.deb with the run-time packages of
#   Debian 12 as dependencies (dpkg-shlibdeps when available).
include(GNUInstallDirs)
# `install` (and cpack's preinstall) need only what is installed, not every test and
# benchmark: build hsmu and hsmu-controller first (CI builds everything before ctest).
set(CMAKE_SKIP_INSTALL_ALL_DEPENDENCY ON)

if(TARGET hsmu)
  install(TARGETS hsmu hsmu-cli hsmu-console RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
endif()
install(TARGETS hsmu-controller RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/resources/presets/
        DESTINATION ${CMAKE_INSTALL_DATADIR}/hsmu/presets FILES_MATCHING PATTERN "*.json")
if(HSMU_QM_FILES)
  install(FILES ${HSMU_QM_FILES} DESTINATION ${CMAKE_INSTALL_DATADIR}/hsmu/translations)
endif()
install(FILES ${PROJECT_SOURCE_DIR}/resources/desktop/hsmu.desktop
        DESTINATION ${CMAKE_INSTALL_DATADIR}/applications)
install(FILES ${PROJECT_SOURCE_DIR}/resources/desktop/hsmu.svg
        DESTINATION ${CMAKE_INSTALL_DATADIR}/icons/hicolor/scalable/apps)
install(FILES ${PROJECT_SOURCE_DIR}/opensees/hsmu_twin.tcl
        DESTINATION ${CMAKE_INSTALL_DATADIR}/hsmu/opensees)
install(FILES ${PROJECT_SOURCE_DIR}/README.md DESTINATION ${CMAKE_INSTALL_DATADIR}/doc/hsmu)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/docs/ DESTINATION ${CMAKE_INSTALL_DATADIR}/doc/hsmu
        FILES_MATCHING PATTERN "*.md")

set(CPACK_PACKAGE_NAME hsmu)
set(CPACK_PACKAGE_VENDOR "HSMU")
set(CPACK_PACKAGE_CONTACT "HSMU maintainers <hsmu@localhost>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "${PROJECT_DESCRIPTION}")
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
# Qt's platform plugins and OpenSSL 3 (loaded on the first tls:// link, comms/tls/OpenSslLibrary)
# are loaded at run time, not linked: name them.
set(CPACK_DEBIAN_PACKAGE_DEPENDS "qt6-qpa-plugins, libqt6svg6, libssl3")
# The Python module (`import hsmu`, docs/python.md) needs the interpreter and NumPy.
if(HSMU_PYTHON_MODULE)
  set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "python3, python3-numpy")
endif()
set(CPACK_GENERATOR DEB)
include(CPack)
