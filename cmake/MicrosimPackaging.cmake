# The install layout and the Debian package. `cmake --install` (or `cpack -G DEB` in a build
# dir) lays microsim out the Debian way under the prefix (/usr in the package):
#   bin/microsim, bin/microsim-cli            the programs (translations and shaders compiled in)
#   share/microsim/                           what they read at run time: lessons, scenes,
#                                             rubrics, meshes, the recorded stitch, the schemas
#   share/applications/microsim.desktop       the desktop entry
#   share/icons/hicolor/scalable/apps/microsim.svg
#   share/man/man1/microsim.1.gz, microsim-cli.1.gz
#   share/doc/microsim/copyright
# The programs find share/microsim beside their own folder (app/lesson/resource_directory.h).
# scripts/package-test.sh builds the package, unpacks it into a temporary root and runs it.

set(MICROSIM_PACKAGING_DIR ${PROJECT_SOURCE_DIR}/packaging)

install(TARGETS microsim microsim-cli RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
# the shaders are Qt resources inside the app, so the folder is left out
install(DIRECTORY ${PROJECT_SOURCE_DIR}/resources/
  DESTINATION ${CMAKE_INSTALL_DATADIR}/microsim
  PATTERN shaders EXCLUDE)
install(FILES ${MICROSIM_PACKAGING_DIR}/microsim.desktop DESTINATION ${CMAKE_INSTALL_DATADIR}/applications)
install(FILES ${MICROSIM_PACKAGING_DIR}/microsim.svg DESTINATION ${CMAKE_INSTALL_DATADIR}/icons/hicolor/scalable/apps)
install(FILES ${MICROSIM_PACKAGING_DIR}/copyright DESTINATION ${CMAKE_INSTALL_DOCDIR})

# man pages: the version filled in, gzipped without a time stamp (Debian policy: gzip -9n)
set(microsim_man_pages "")
foreach(page microsim microsim-cli)
  set(man_page ${PROJECT_BINARY_DIR}/packaging/${page}.1)
  configure_file(${MICROSIM_PACKAGING_DIR}/${page}.1.in ${man_page} @ONLY)
  add_custom_command(OUTPUT ${man_page}.gz
    COMMAND gzip -9nkf ${man_page}
    DEPENDS ${man_page}
    COMMENT "Compressing the man page ${page}.1")
  list(APPEND microsim_man_pages ${man_page}.gz)
endforeach()
add_custom_target(microsim_man_pages ALL DEPENDS ${microsim_man_pages})
install(FILES ${microsim_man_pages} DESTINATION ${CMAKE_INSTALL_MANDIR}/man1)

# the Debian package; dpkg-shlibdeps (dpkg-dev) derives Depends from the programs' libraries,
# and the Qt plugins they load by name are added by hand
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME microsim)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_CONTACT "microsim maintainers <maintainers@users.noreply.h-seed-2b0ccdfe.example>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "training simulator for surgical micro-anastomosis")
# Debian's long description: lines under 80 columns, an empty line between paragraphs
set(CPACK_PACKAGE_DESCRIPTION [=[
Surgical residents practise repairing a severed blood vessel of about 1 mm
with two forceps, a needle and a suture under a virtual operating microscope,
and are graded on it: five lessons in Learn and Test mode, scores with
feedback, a trainee history (SQLite or PostgreSQL) that instructors review
with replays, and calibration of the OpenIGTLink trackers that drive the
forceps.

The package holds the desktop program, microsim, and microsim-cli, which
solves, replays, scores and benchmarks without a display and manages the
history.]=])
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_STRIP_FILES ON)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_RELEASE 1)
set(CPACK_DEBIAN_PACKAGE_SECTION education)
set(CPACK_DEBIAN_PACKAGE_PRIORITY optional)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
# the history's SQLite driver is a plugin that no ELF header names
set(CPACK_DEBIAN_PACKAGE_DEPENDS "libqt6sql6-sqlite")
# PostgreSQL histories, Qt's own German and Spanish texts, hardware OpenGL drivers
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "libqt6sql6-psql, qt6-translations-l10n, libgl1-mesa-dri")
# the 3D mouse's daemon: libspnav (found by dpkg-shlibdeps like SDL2 and Qt) talks to
# spacenavd, which only a user with a 3D mouse needs
set(CPACK_DEBIAN_PACKAGE_SUGGESTS "spacenavd")
include(CPack)
