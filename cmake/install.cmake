# What `cmake --install build --prefix P` puts where (docs/install.md), libtippe.so
# with its pkg-config file, the man pages and bash completion generated from
# --help, and the .deb (CPack; tools/deb.sh).

# libtippe.so: the library's objects (the same that make libtippe.a and the command)
# as a shared library with a SONAME; its stable part is the installed headers
# (docs/library.md). Its ABI number changes whenever that part breaks.
set(TIPPE_SOVERSION 0)
add_library(tippe_shared SHARED ${TIPPE_CORE_OBJECTS} ${TIPPE_HEAVY_OBJECTS})
target_link_libraries(tippe_shared PRIVATE tippe_base ${TIPPE_HEAVY_LIBS})
set_target_properties(tippe_shared PROPERTIES OUTPUT_NAME tippe VERSION ${PROJECT_VERSION}
  SOVERSION ${TIPPE_SOVERSION} LIBRARY_OUTPUT_DIRECTORY ${PROJECT_BINARY_DIR})
target_link_options(tippe_shared PRIVATE -Wl,--no-undefined
  -Wl,--version-script=${PROJECT_SOURCE_DIR}/cmake/libtippe.map)
set_property(TARGET tippe_shared APPEND PROPERTY LINK_DEPENDS ${PROJECT_SOURCE_DIR}/cmake/libtippe.map)

# Man pages (one per verb and tippe(1)) and the bash completion, from the built
# command's --help at build time (tools/gen_man.py): they cannot drift from it.
set(TIPPE_MAN_DIR ${PROJECT_BINARY_DIR}/man)
set(TIPPE_COMPLETION ${PROJECT_BINARY_DIR}/completion/tippe)
find_package(Python3 COMPONENTS Interpreter REQUIRED)
add_custom_command(OUTPUT ${TIPPE_MAN_DIR}/tippe.1.gz ${TIPPE_COMPLETION}
  COMMAND ${Python3_EXECUTABLE} ${PROJECT_SOURCE_DIR}/tools/gen_man.py $<TARGET_FILE:tippe-cli>
          ${TIPPE_MAN_DIR} ${TIPPE_COMPLETION}
  DEPENDS tippe-cli ${PROJECT_SOURCE_DIR}/tools/gen_man.py
  COMMENT "Man pages and bash completion from tippe --help" VERBATIM)
add_custom_target(tippe_man ALL DEPENDS ${TIPPE_MAN_DIR}/tippe.1.gz ${TIPPE_COMPLETION})

# pkg-config: Requires.private lists what a static link would need; the shared
# library carries its own dependencies.
# prefix relative to the .pc file itself: an install under any prefix is found.
file(RELATIVE_PATH TIPPE_PC_TO_PREFIX /P/${CMAKE_INSTALL_LIBDIR}/pkgconfig /P)
string(REGEX REPLACE "/$" "" TIPPE_PC_TO_PREFIX "${TIPPE_PC_TO_PREFIX}")
configure_file(${PROJECT_SOURCE_DIR}/cmake/tippe.pc.in ${PROJECT_BINARY_DIR}/tippe.pc @ONLY)

install(TARGETS tippe-cli RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
if(TARGET tippe-mpi)
  install(TARGETS tippe-mpi RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
endif()
foreach(module ${TIPPE_MODULES} serve)
  install(TARGETS tippe_${module}_module LIBRARY DESTINATION ${TIPPE_MODULE_DEST})
endforeach()
install(TARGETS tippe_shared LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
# The stable headers (docs/library.md) and those they include.
install(FILES ${PROJECT_SOURCE_DIR}/include/tippe/base.h ${PROJECT_SOURCE_DIR}/include/tippe/print.h
  ${PROJECT_SOURCE_DIR}/include/tippe/design.h ${PROJECT_SOURCE_DIR}/include/tippe/physics.h
  ${PROJECT_SOURCE_DIR}/include/tippe/scenario.h ${PROJECT_SOURCE_DIR}/include/tippe/sweep.h
  ${PROJECT_SOURCE_DIR}/include/tippe/top.h ${PROJECT_SOURCE_DIR}/include/tippe/theory.h
  ${PROJECT_SOURCE_DIR}/include/tippe/launch.h
  DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/tippe)
install(FILES ${PROJECT_BINARY_DIR}/tippe.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/designs/ DESTINATION ${TIPPE_DATA_DEST})
install(DIRECTORY ${TIPPE_MAN_DIR}/ DESTINATION ${CMAKE_INSTALL_MANDIR}/man1 FILES_MATCHING PATTERN "*.1.gz")
install(FILES ${TIPPE_COMPLETION} DESTINATION ${CMAKE_INSTALL_DATADIR}/bash-completion/completions)

# The Python module (python/tippe, docs/python.md) where Debian's python3 looks for
# packages, with _install.py saying where libtippe is from there.
set(TIPPE_PYTHON_DEST lib/python3/dist-packages CACHE STRING
    "where cmake --install puts the Python module tippe, relative to the prefix")
file(RELATIVE_PATH TIPPE_PY_TO_LIB /P/${TIPPE_PYTHON_DEST}/tippe
     /P/${CMAKE_INSTALL_LIBDIR}/libtippe.so.${TIPPE_SOVERSION})
file(WRITE ${PROJECT_BINARY_DIR}/python/_install.py
     "# Written by cmake --install (cmake/install.cmake): libtippe, relative to this folder.\n"
     "LIBRARY = \"${TIPPE_PY_TO_LIB}\"\n")
install(FILES ${PROJECT_SOURCE_DIR}/python/tippe/__init__.py ${PROJECT_BINARY_DIR}/python/_install.py
  DESTINATION ${TIPPE_PYTHON_DEST}/tippe)

# The .deb (tools/deb.sh; docs/install.md). Depends: what dpkg-shlibdeps reads from the
# ELF files it ships (the command, libtippe, the modules), plus the libraries tippe opens
# itself by SONAME, which no ELF file names (NLopt for optimise, FFmpeg's for animate: see
# src/optimise/optimise_search.c, src/animate/encode.c), and PLplot's cairo driver, which
# PLplot loads at run time: their Debian packages are asked of dpkg here.
set(TIPPE_DLOPENED nlopt avcodec avformat avutil swscale avfilter)
set(TIPPE_DEB_EXTRA plplot-driver-cairo)
find_program(DPKG_QUERY dpkg)
foreach(lib ${TIPPE_DLOPENED})
  find_library(TIPPE_DLOPEN_${lib} ${lib})
  if(DPKG_QUERY AND TIPPE_DLOPEN_${lib})
    execute_process(COMMAND ${CMAKE_OBJDUMP} -p ${TIPPE_DLOPEN_${lib}} OUTPUT_VARIABLE dump ERROR_QUIET)
    if(dump MATCHES "SONAME +([^ \n]+)")
      execute_process(COMMAND ${DPKG_QUERY} -S "*/${CMAKE_MATCH_1}" OUTPUT_VARIABLE owner
                      ERROR_QUIET OUTPUT_STRIP_TRAILING_WHITESPACE)
      if(owner MATCHES "^([^:, ]+)")
        list(APPEND TIPPE_DEB_EXTRA ${CMAKE_MATCH_1})
      endif()
    endif()
  endif()
endforeach()
list(REMOVE_DUPLICATES TIPPE_DEB_EXTRA)
string(REPLACE ";" ", " TIPPE_DEB_EXTRA "${TIPPE_DEB_EXTRA}")
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME tippe)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(TIPPE_DEB_MAINTAINER "tippe maintainers <tippe@example.org>" CACHE STRING
    "the .deb's Maintainer field (name <address>)")
set(CPACK_PACKAGE_CONTACT "${TIPPE_DEB_MAINTAINER}")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "design and check 3D-printed spherical tippe tops")
set(CPACK_PACKAGE_DESCRIPTION "tippe computes the mass model of a spherical tippe top
design, sweeps the position of its moving weight for the zones of Theorem 5.1
(Ciocci et al. 2012), integrates launches, exports printable files and serves
a local web page. Includes libtippe (C, pkg-config tippe) and the Python
module tippe.")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
# the shlibs file and the ldconfig trigger written here (cmake/debian/): CPack's own
# would call ldconfig from maintainer scripts, which Debian replaced by the trigger
set(CPACK_DEBIAN_PACKAGE_GENERATE_SHLIBS OFF)
file(WRITE ${PROJECT_BINARY_DIR}/debian/shlibs
     "libtippe ${TIPPE_SOVERSION} tippe (>= ${PROJECT_VERSION})\n")
file(WRITE ${PROJECT_BINARY_DIR}/debian/triggers "activate-noawait ldconfig\n")
# CPack adds a postinst and a postrm calling ldconfig, which the trigger replaces;
# tools/deb.sh takes them out again (a package with a postrm stays known to dpkg
# after apt remove, as "rc", although none of its files is left).
set(CPACK_DEBIAN_PACKAGE_CONTROL_EXTRA ${PROJECT_BINARY_DIR}/debian/shlibs
    ${PROJECT_BINARY_DIR}/debian/triggers)
set(CPACK_DEBIAN_PACKAGE_DEPENDS "${TIPPE_DEB_EXTRA}")
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "python3, python3-numpy, bash-completion")
set(CPACK_DEBIAN_PACKAGE_SUGGESTS "prusa-slicer, openscad, python3-matplotlib, openmpi-bin")
set(CPACK_DEBIAN_PACKAGE_CONTROL_STRICT_PERMISSION ON)
set(CPACK_STRIP_FILES ON)
# /usr/share/doc/tippe: copyright and the changelog, gzipped without a time stamp
find_program(GZIP_PROGRAM gzip REQUIRED)
execute_process(COMMAND ${GZIP_PROGRAM} -9nc ${PROJECT_SOURCE_DIR}/cmake/debian/changelog
                OUTPUT_FILE ${PROJECT_BINARY_DIR}/debian/changelog.gz)
install(FILES ${PROJECT_SOURCE_DIR}/cmake/debian/copyright ${PROJECT_BINARY_DIR}/debian/changelog.gz
        DESTINATION ${CMAKE_INSTALL_DOCDIR})
include(CPack)
