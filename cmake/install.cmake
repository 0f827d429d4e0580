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
add_custom_command(OUTPUT ${TIPPE_MAN_DIR}/tippe.1 ${TIPPE_COMPLETION}
  COMMAND ${Python3_EXECUTABLE} ${PROJECT_SOURCE_DIR}/tools/gen_man.py $<TARGET_FILE:tippe-cli>
          ${TIPPE_MAN_DIR} ${TIPPE_COMPLETION}
  DEPENDS tippe-cli ${PROJECT_SOURCE_DIR}/tools/gen_man.py
  COMMENT "Man pages and bash completion from tippe --help" VERBATIM)
add_custom_target(tippe_man ALL DEPENDS ${TIPPE_MAN_DIR}/tippe.1 ${TIPPE_COMPLETION})

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
  DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/tippe)
install(FILES ${PROJECT_BINARY_DIR}/tippe.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/designs/ DESTINATION ${TIPPE_DATA_DEST})
install(DIRECTORY ${TIPPE_MAN_DIR}/ DESTINATION ${CMAKE_INSTALL_MANDIR}/man1 FILES_MATCHING PATTERN "*.1")
install(FILES ${TIPPE_COMPLETION} DESTINATION ${CMAKE_INSTALL_DATADIR}/bash-completion/completions)
