# `cmake --install build [--prefix DIR]` and `cpack` (docs/install.md).
#
#   bin/dermis                          the program
#   share/dermis/{shaders,content,tools} its data (core/DataDirectory.h finds
#                                        it from bin/ wherever the tree moves)
#   include/dermis, lib/*.a             the engine, one library per layer
#   lib/cmake/Dermis                    find_package(Dermis): Dermis::engine
#
# Components: "runtime" (program and data) and "development" (the rest).
include(CMakePackageConfigHelpers)

install(TARGETS dermis RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} COMPONENT runtime)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/shaders ${PROJECT_SOURCE_DIR}/content
        DESTINATION ${CMAKE_INSTALL_DATADIR}/dermis COMPONENT runtime)
# The scripts the program runs (plots) and the ones its docs tell users to run.
file(GLOB DERMIS_TOOL_SCRIPTS CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/tools/*.py ${PROJECT_SOURCE_DIR}/tools/*.sh)
list(REMOVE_ITEM DERMIS_TOOL_SCRIPTS ${PROJECT_SOURCE_DIR}/tools/setup.sh)
install(PROGRAMS ${DERMIS_TOOL_SCRIPTS} DESTINATION ${CMAKE_INSTALL_DATADIR}/dermis/tools COMPONENT runtime)
install(FILES ${PROJECT_SOURCE_DIR}/README.md DESTINATION ${CMAKE_INSTALL_DOCDIR} COMPONENT runtime)

configure_package_config_file(${PROJECT_SOURCE_DIR}/tools/cmake/DermisConfig.cmake.in
    ${PROJECT_BINARY_DIR}/generated/DermisConfig.cmake INSTALL_DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/Dermis)
write_basic_package_version_file(${PROJECT_BINARY_DIR}/generated/DermisConfigVersion.cmake
    COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/generated/DermisConfig.cmake ${PROJECT_BINARY_DIR}/generated/DermisConfigVersion.cmake
        DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/Dermis COMPONENT development)

# `cpack --config build/CPackConfig.cmake`: one .deb with both components,
# its library dependencies worked out by dpkg-shlibdeps.
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME dermis)
set(CPACK_PACKAGE_VENDOR "Dermis developers")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "Real-time skin renderer: screen-space and texture-space subsurface scattering")
set(CPACK_PACKAGE_CONTACT "Dermis developers <dermis@localhost>")
set(CPACK_PACKAGE_DIRECTORY ${PROJECT_BINARY_DIR}/packages)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION graphics)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
# Headers and the CMake package need the engine's development packages; the
# plots need matplotlib.
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "python3-matplotlib, python3-numpy")
set(CPACK_DEBIAN_PACKAGE_SUGGESTS "libglm-dev, nlohmann-json3-dev, libopenimageio-dev, libembree-dev, libmeshoptimizer-dev, libdraco-dev, libegl-dev, libosmesa6-dev, libtinygltf-dev")
set(CPACK_STRIP_FILES ON)
set(CPACK_PACKAGING_INSTALL_PREFIX ${DERMIS_PACKAGE_PREFIX})
include(CPack)
