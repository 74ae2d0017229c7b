# What `cmake --install` puts in place for consumers: the library, headers and exporters, the
# CMake package, a pkg-config file and the licence.
# The targets themselves join the export set in raster_setup_target(... INSTALL).
include(CMakePackageConfigHelpers)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/include/raster ${PROJECT_BINARY_DIR}/src/generated/raster
  DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
set(RASTER_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/raster)

install(EXPORT raster-targets NAMESPACE raster:: DESTINATION ${RASTER_CMAKE_DIR} FILE raster-targets.cmake)
if(BUILD_SHARED_LIBS)
  set(RASTER_NEEDS_WEBP_AT_LINK FALSE)
else()
  set(RASTER_NEEDS_WEBP_AT_LINK TRUE)
endif()
configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/raster-config.cmake.in
  ${PROJECT_BINARY_DIR}/raster-config.cmake INSTALL_DESTINATION ${RASTER_CMAKE_DIR})
# Before 1.0 a minor release may change the API, so only the same minor version is compatible.
write_basic_package_version_file(${PROJECT_BINARY_DIR}/raster-config-version.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/raster-config.cmake ${PROJECT_BINARY_DIR}/raster-config-version.cmake
  DESTINATION ${RASTER_CMAKE_DIR})

# The .pc file finds its prefix from where it lies, so `cmake --install --prefix` can move it.
file(RELATIVE_PATH RASTER_PC_TO_PREFIX "/${CMAKE_INSTALL_LIBDIR}/pkgconfig" "/")
string(REGEX REPLACE "/$" "" RASTER_PC_TO_PREFIX "${RASTER_PC_TO_PREFIX}")
# A static library needs its image and model libraries at every link; a shared one only inside itself.
set(RASTER_PC_WEBP "libwebp libwebpmux libwebpdemux libpng stb tinyobjloader assimp")
if(BUILD_SHARED_LIBS)
  set(RASTER_PC_REQUIRES "glm")
  set(RASTER_PC_REQUIRES_PRIVATE "${RASTER_PC_WEBP}")
else()
  set(RASTER_PC_REQUIRES "glm ${RASTER_PC_WEBP}")
  set(RASTER_PC_REQUIRES_PRIVATE "")
endif()
configure_file(${CMAKE_CURRENT_LIST_DIR}/raster.pc.in ${PROJECT_BINARY_DIR}/raster.pc @ONLY)
configure_file(${CMAKE_CURRENT_LIST_DIR}/raster-scenes.pc.in ${PROJECT_BINARY_DIR}/raster-scenes.pc @ONLY)
install(FILES ${PROJECT_BINARY_DIR}/raster.pc ${PROJECT_BINARY_DIR}/raster-scenes.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)

install(FILES ${PROJECT_SOURCE_DIR}/LICENSE ${PROJECT_SOURCE_DIR}/README.md ${PROJECT_SOURCE_DIR}/CHANGELOG.md
  DESTINATION ${CMAKE_INSTALL_DATAROOTDIR}/doc/raster)
