# Installing Inlay like a Linux desktop program, and its Debian package (CPack).
#
#   cmake --install build --prefix P     (or: cpack --config build/CPackConfig.cmake -G DEB)
#
# P/bin/inlay, P/bin/inlay-cli
# P/share/inlay/example/        the bundled example (engine/data_dirs.h finds it beside bin/)
# P/share/inlay/models/         the model library, when resources/models/ exists
# P/share/inlay/translations/   inlay_<lang>.qm (also embedded in the studio)
# P/share/icons/hicolor/...     the icon, SVG and PNG
# P/share/applications/inlay.desktop
# P/share/man/man1/inlay-cli.1.gz, inlay.1.gz   from the programs' own --help (ManPage.cmake)
# P/share/doc/inlay/            README.md and docs/ (their links kept), copyright, changelog
#
# Included after the targets exist (the man pages run them).

set(INLAY_DATA_DEST ${CMAKE_INSTALL_DATADIR}/inlay)
# The Maintainer field and the changelog's signature: example.org until the project names one.
set(INLAY_PACKAGE_MAINTAINER "Inlay developers <inlay@example.org>" CACHE STRING
    "The .deb's Maintainer (name <address>)")

# --- The programs -------------------------------------------------------------------------------
# Debian's hardening: full RELRO (the GOT read-only after start).
foreach(program inlay-cli inlay)
  if(TARGET ${program})
    target_link_options(${program} PRIVATE -Wl,-z,relro -Wl,-z,now)
  endif()
endforeach()

# --- Data ---------------------------------------------------------------------------------------
install(DIRECTORY ${CMAKE_SOURCE_DIR}/resources/example DESTINATION ${INLAY_DATA_DEST})
# The model library (resources/models/): its meshes, thumbnails and index, not the code that
# generates them. OPTIONAL: no error while the folder is absent.
install(DIRECTORY ${CMAKE_SOURCE_DIR}/resources/models DESTINATION ${INLAY_DATA_DEST} OPTIONAL
        PATTERN "generator" EXCLUDE PATTERN "CMakeLists.txt" EXCLUDE
        PATTERN "*.cpp" EXCLUDE PATTERN "*.h" EXCLUDE PATTERN "*.py" EXCLUDE)

# --- Desktop integration ------------------------------------------------------------------------
# The PNGs are the SVG rendered by `rsvg-convert -w N -h N resources/icons/inlay.svg`.
install(FILES ${CMAKE_SOURCE_DIR}/resources/icons/inlay.svg
        DESTINATION ${CMAKE_INSTALL_DATADIR}/icons/hicolor/scalable/apps)
foreach(size 16 32 48 64 128 256)
  install(FILES ${CMAKE_SOURCE_DIR}/resources/icons/hicolor/${size}x${size}/apps/inlay.png
          DESTINATION ${CMAKE_INSTALL_DATADIR}/icons/hicolor/${size}x${size}/apps)
endforeach()
if(BUILD_APP)
  install(FILES ${CMAKE_SOURCE_DIR}/resources/packaging/inlay.desktop
          DESTINATION ${CMAKE_INSTALL_DATADIR}/applications)
endif()

# --- Man pages, from the same text as --help ----------------------------------------------------
# cmake/ManPage.cmake runs the built program (--help, --version) and writes its words verbatim.
function(inlay_man_page target summary)
  set(page ${CMAKE_BINARY_DIR}/man/${target}.1)
  add_custom_command(OUTPUT ${page}.gz
    COMMAND ${CMAKE_COMMAND} -E make_directory ${CMAKE_BINARY_DIR}/man
    COMMAND ${CMAKE_COMMAND} -DPROGRAM=$<TARGET_FILE:${target}> -DNAME=${target}
            -DSUMMARY=${summary} -DOUTPUT=${page}
            -DSEE_ALSO_FILE=${CMAKE_SOURCE_DIR}/resources/packaging/man-see-also.roff
            -P ${CMAKE_SOURCE_DIR}/cmake/ManPage.cmake
    DEPENDS ${target} ${CMAKE_SOURCE_DIR}/cmake/ManPage.cmake
            ${CMAKE_SOURCE_DIR}/resources/packaging/man-see-also.roff
    COMMENT "Man page ${target}.1 from ${target} --help" VERBATIM)
  add_custom_target(${target}_man ALL DEPENDS ${page}.gz)
  # OPTIONAL: a tree built only in part (--target inlay-cli) still installs.
  install(FILES ${page}.gz DESTINATION ${CMAKE_INSTALL_MANDIR}/man1 OPTIONAL)
endfunction()
if(CMAKE_CROSSCOMPILING)
  message(STATUS "cross-compiling: no man pages (they run the built programs)")
else()
  inlay_man_page(inlay-cli "insert synthetic 3D objects into a photograph (command line)")
  if(BUILD_APP)
    inlay_man_page(inlay "insert synthetic 3D objects into a photograph (the studio)")
  endif()
endif()

# --- Documentation ------------------------------------------------------------------------------
install(FILES ${CMAKE_SOURCE_DIR}/README.md ${CMAKE_SOURCE_DIR}/resources/packaging/copyright
        DESTINATION ${CMAKE_INSTALL_DOCDIR})
install(DIRECTORY ${CMAKE_SOURCE_DIR}/docs DESTINATION ${CMAKE_INSTALL_DOCDIR}
        PATTERN "*.py" EXCLUDE)
# Debian wants a changelog.gz beside the copyright (gzip -9n: no timestamp).
configure_file(${CMAKE_SOURCE_DIR}/resources/packaging/changelog.in ${CMAKE_BINARY_DIR}/packaging/changelog @ONLY)
add_custom_command(OUTPUT ${CMAKE_BINARY_DIR}/packaging/changelog.gz
  COMMAND gzip -9nkf ${CMAKE_BINARY_DIR}/packaging/changelog
  DEPENDS ${CMAKE_BINARY_DIR}/packaging/changelog VERBATIM)
add_custom_target(inlay_changelog ALL DEPENDS ${CMAKE_BINARY_DIR}/packaging/changelog.gz)
install(FILES ${CMAKE_BINARY_DIR}/packaging/changelog.gz DESTINATION ${CMAKE_INSTALL_DOCDIR} OPTIONAL)

# --- The Debian package -------------------------------------------------------------------------
# cpack --config build/CPackConfig.cmake -G DEB writes inlay_<version>_<arch>.deb. Its runtime
# dependencies are found by dpkg-shlibdeps (Debian's dpkg-dev) from the binaries' libraries;
# what they load at run time without linking is declared by hand.
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME inlay)
set(CPACK_PACKAGE_VENDOR "The Inlay authors")
set(CPACK_PACKAGE_CONTACT "${INLAY_PACKAGE_MAINTAINER}")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "insert synthetic 3D objects into photographs")
string(JOIN "\n" CPACK_PACKAGE_DESCRIPTION
  "Inlay places 3D objects into an ordinary photograph so that they look as if"
  "they had been there: right perspective, lit by the room's own lights, casting"
  "shadows and bouncing light onto the real floor."
  ""
  "It fits a box room to the photo, estimates the room's albedo and its lights,"
  "renders the scene with and without the objects with a path tracer, and"
  "composites the difference into the photo."
  ""
  "The package holds the studio (inlay) and the command line (inlay-cli).")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_STRIP_FILES ON)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION graphics)
set(CPACK_DEBIAN_PACKAGE_PRIORITY optional)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
if(BUILD_APP)
  # Loaded as plugins, not linked: the X11/Wayland platforms, the SVG window icon, Qt's own
  # German and French strings.
  set(CPACK_DEBIAN_PACKAGE_DEPENDS "qt6-qpa-plugins")
  set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "libqt6svg6, qt6-translations-l10n")
endif()
include(CPack)
