# Installs the build into a fresh prefix, then builds and runs consumers against it:
# find_package, pkg-config, or add_subdirectory (MODE), each from a clean directory.
# cmake -DMODE=find_package|pkg_config|subdirectory -DSOURCE=... -DBUILD=... -DWORK=... -P check_package.cmake
cmake_minimum_required(VERSION 3.25)
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})

function(run)
  execute_process(COMMAND ${ARGN} WORKING_DIRECTORY ${WORK} COMMAND_ERROR_IS_FATAL ANY)
endfunction()

function(expect_webp file)
  file(READ ${file} header LIMIT 16 HEX)
  if(NOT header MATCHES "^52494646........57454250")  # "RIFF" size "WEBP"
    message(FATAL_ERROR "${file} is not a WebP file")
  endif()
endfunction()

if(MODE STREQUAL "subdirectory")
  run(${CMAKE_COMMAND} -S ${SOURCE}/tests/package/subdirectory -B ${WORK}/build -DRASTER_SOURCE_DIR=${SOURCE}
      -DCMAKE_BUILD_TYPE=Release)
  run(${CMAKE_COMMAND} --build ${WORK}/build -j 2)
  run(${WORK}/build/consumer ${WORK}/out.webp)
  expect_webp(${WORK}/out.webp)
  return()
endif()

run(${CMAKE_COMMAND} --install ${BUILD} --prefix ${WORK}/prefix)
foreach(installed include/raster/raster.hpp include/raster/rasterize/fill.hpp include/raster/scenes/scenes.hpp include/raster/version.hpp bin/still-cube bin/webp-frame
                  share/doc/raster/LICENSE)
  if(NOT EXISTS ${WORK}/prefix/${installed})
    message(FATAL_ERROR "cmake --install did not install ${installed}")
  endif()
endforeach()
file(GLOB_RECURSE config ${WORK}/prefix/*/raster-config.cmake)
file(GLOB_RECURSE config_version ${WORK}/prefix/*/raster-config-version.cmake)
file(GLOB_RECURSE pc ${WORK}/prefix/*/raster.pc)
file(GLOB_RECURSE scenes_pc ${WORK}/prefix/*/raster-scenes.pc)
if(NOT config OR NOT config_version OR NOT pc OR NOT scenes_pc)
  message(FATAL_ERROR "missing raster-config.cmake, raster-config-version.cmake, raster.pc or raster-scenes.pc")
endif()
run(${WORK}/prefix/bin/still-unit-cube --quiet ${WORK}/unit.webp)
expect_webp(${WORK}/unit.webp)

if(MODE STREQUAL "find_package")
  run(${CMAKE_COMMAND} -S ${SOURCE}/tests/package/consumer -B ${WORK}/build -DCMAKE_PREFIX_PATH=${WORK}/prefix
      -DCMAKE_BUILD_TYPE=Release)
  run(${CMAKE_COMMAND} --build ${WORK}/build)
  run(${WORK}/build/consumer ${WORK}/out.webp)
elseif(MODE STREQUAL "pkg_config")
  cmake_path(GET pc PARENT_PATH pc_dir)
  set(ENV{PKG_CONFIG_PATH} ${pc_dir})
  execute_process(COMMAND pkg-config --cflags --libs raster-scenes OUTPUT_VARIABLE flags
                  OUTPUT_STRIP_TRAILING_WHITESPACE COMMAND_ERROR_IS_FATAL ANY)
  separate_arguments(flags UNIX_COMMAND "${flags}")
  run(c++ -std=c++20 ${SOURCE}/tests/package/consumer/main.cpp -o ${WORK}/consumer ${flags})
  run(${WORK}/consumer ${WORK}/out.webp)
else()
  message(FATAL_ERROR "unknown MODE '${MODE}'")
endif()
expect_webp(${WORK}/out.webp)
