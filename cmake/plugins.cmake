# Plugins (core/plugin.h) and the installed package: `cmake --install build
# --prefix P` puts the headers in P/include/icpbench (included as
# "core/interval.h"), the static libraries in P/lib, the binary in P/bin and
# the package that find_package(icpbench) reads in P/lib/cmake/icpbench.

# How a --plugin library reaches icpbench's code: it links none of it. The
# icpbench executable exports its symbols (ENABLE_EXPORTS: -rdynamic) and
# carries the whole of icp_core, icp_algorithms and icp_problems, not only the
# archive members it calls itself, so dlopen resolves every function of the
# installed headers that a plugin calls, the registries' among them, from the
# executable: one registry. A plugin that linked the static libraries would
# carry a second copy of the tables and of every other global, and which copy
# a call reached would depend on the order of symbol lookup. The libraries
# come to the executable through icp_harness; the overrides (CMake 3.24) give
# them the WHOLE_ARCHIVE feature there.
set_target_properties(icpbench PROPERTIES
  ENABLE_EXPORTS ON
  LINK_LIBRARY_OVERRIDE_icp_core WHOLE_ARCHIVE
  LINK_LIBRARY_OVERRIDE_icp_algorithms WHOLE_ARCHIVE
  LINK_LIBRARY_OVERRIDE_icp_problems WHOLE_ARCHIVE)

# icpbench::plugin: what a plugin compiles against, the headers and their
# public dependencies, and no code.
add_library(icpbench_plugin_api INTERFACE)
target_link_libraries(icpbench_plugin_api INTERFACE Boost::headers opencv_core)
target_compile_features(icpbench_plugin_api INTERFACE cxx_std_20)
set_target_properties(icpbench_plugin_api PROPERTIES EXPORT_NAME plugin)
add_library(icpbench::plugin ALIAS icpbench_plugin_api)

# icpbench::icpbench: the static libraries, for a program that embeds the
# framework (its own tool, the unit tests of a plugin's contractor), never
# for a plugin. Position-independent (CMAKE_POSITION_INDEPENDENT_CODE), so
# that a shared library may embed them too.
add_library(icpbench_library INTERFACE)
target_link_libraries(icpbench_library INTERFACE icpbench_plugin_api icp_core icp_algorithms
                      icp_problems)
set_target_properties(icpbench_library PROPERTIES EXPORT_NAME icpbench)
add_library(icpbench::icpbench ALIAS icpbench_library)

include(GNUInstallDirs)
include(CMakePackageConfigHelpers)
set(ICPBENCH_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/icpbench)

install(TARGETS icpbench RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(TARGETS icp_core icp_algorithms icp_problems icpbench_plugin_api icpbench_library
        EXPORT icpbench-targets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/icpbench)
# Read at install time, so a new header needs no line here.
install(DIRECTORY core algorithms problems
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/icpbench
        FILES_MATCHING PATTERN "*.h" PATTERN "data" EXCLUDE)
install(EXPORT icpbench-targets NAMESPACE icpbench:: DESTINATION ${ICPBENCH_CMAKE_DIR})

configure_package_config_file(cmake/icpbench-config.cmake.in
  ${CMAKE_BINARY_DIR}/icpbench-config.cmake INSTALL_DESTINATION ${ICPBENCH_CMAKE_DIR})
# The C++ types a plugin shares with the executable are no stable ABI: a
# requested version must match exactly.
write_basic_package_version_file(${CMAKE_BINARY_DIR}/icpbench-config-version.cmake
  COMPATIBILITY ExactVersion)
install(FILES ${CMAKE_BINARY_DIR}/icpbench-config.cmake
              ${CMAKE_BINARY_DIR}/icpbench-config-version.cmake
        DESTINATION ${ICPBENCH_CMAKE_DIR})
