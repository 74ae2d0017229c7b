# How every target of raster's own is built: raster_options, link-time optimisation, its
# raster:: name and its place in the installed package. Nothing here sets a global flag.

# Warnings as errors (and any sanitizers) for our own targets only; third-party headers come in
# as SYSTEM.
add_library(raster_options INTERFACE)
if(RASTER_SANITIZE)
  set(sanitize_flags -fsanitize=${RASTER_SANITIZE} -fno-sanitize-recover=all -fno-omit-frame-pointer)
  target_compile_options(raster_options INTERFACE ${sanitize_flags})
  target_link_options(raster_options INTERFACE ${sanitize_flags})
endif()
if(RASTER_BUILD_FUZZERS)
  target_compile_options(raster_options INTERFACE -fsanitize=fuzzer-no-link)
endif()
# The instruction set every binary may use: x86-64-v2 (SSE4.2, any x86-64 CPU since 2009) by
# default, so SIMD lanes get blends and rounding in one instruction. No multiply-add is ever
# fused, whatever the set, so pictures stay the same bit for bit on every CPU (doc/conventions.md#lanes).
if(CMAKE_SYSTEM_PROCESSOR MATCHES "x86_64|AMD64" AND CMAKE_SIZEOF_VOID_P EQUAL 8)
  set(raster_default_arch x86-64-v2)
else()
  set(raster_default_arch "")
endif()
set(RASTER_ARCH "${raster_default_arch}" CACHE STRING "-march for our own code (empty: the compiler's default)")
target_compile_options(raster_options INTERFACE
  $<$<BOOL:${RASTER_ARCH}>:-march=${RASTER_ARCH}>
  $<$<CXX_COMPILER_ID:GNU,Clang>:-ffp-contract=off>)
target_compile_options(raster_options INTERFACE
  $<$<CXX_COMPILER_ID:GNU,Clang>:-Wall -Wextra -Wpedantic -Wshadow -Wconversion -Wold-style-cast -Werror>
  # GCC 12 misreports std::string concatenation under -O2 (GCC bug 105329).
  $<$<CXX_COMPILER_ID:GNU>:-Wno-restrict>)
# Its link-time optimiser misreports std::string copies the same way, as a warning at link.
target_link_options(raster_options INTERFACE $<$<AND:$<BOOL:${RASTER_LTO}>,$<CONFIG:Release>,$<CXX_COMPILER_ID:GNU>>:-Wno-stringop-overflow>)

# raster_setup_target(<target> [ALIAS <name>] [INSTALL] [FUZZER])
#   ALIAS    adds raster::<name> (and exports the target under that name)
#   INSTALL  puts the target in the package: `cmake --install` and raster-targets.cmake
#   FUZZER   links libFuzzer's main
function(raster_setup_target target)
  cmake_parse_arguments(PARSE_ARGV 1 arg "INSTALL;FUZZER" "ALIAS" "")
  if(arg_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "raster_setup_target(${target}): unknown arguments ${arg_UNPARSED_ARGUMENTS}")
  endif()
  get_target_property(type ${target} TYPE)

  target_compile_features(${target} PUBLIC cxx_std_20)
  set_target_properties(${target} PROPERTIES CXX_EXTENSIONS OFF)
  # Not exported: the warnings and sanitizers are ours, not a consumer's.
  target_link_libraries(${target} PRIVATE $<BUILD_INTERFACE:raster_options>)
  if(RASTER_LTO)
    set_target_properties(${target} PROPERTIES INTERPROCEDURAL_OPTIMIZATION_RELEASE ON)
  endif()
  if(arg_FUZZER)
    target_link_options(${target} PRIVATE -fsanitize=fuzzer)
  endif()

  if(arg_ALIAS)
    if(type STREQUAL "EXECUTABLE")
      add_executable(raster::${arg_ALIAS} ALIAS ${target})
    else()
      add_library(raster::${arg_ALIAS} ALIAS ${target})
    endif()
    set_target_properties(${target} PROPERTIES EXPORT_NAME ${arg_ALIAS})
  endif()

  if(arg_INSTALL)
    if(type MATCHES "LIBRARY$")
      # Before 1.0 a minor release may change the ABI, so the soname carries major.minor.
      set_target_properties(${target} PROPERTIES
        VERSION ${PROJECT_VERSION} SOVERSION ${PROJECT_VERSION_MAJOR}.${PROJECT_VERSION_MINOR})
      if(RASTER_LTO)
        # Fat objects: an installed libraster.a links into projects built without LTO, or with clang.
        target_compile_options(${target} PRIVATE $<$<AND:$<CONFIG:Release>,$<CXX_COMPILER_ID:GNU>>:-ffat-lto-objects>)
      endif()
    endif()
    if(RASTER_INSTALL)
      install(TARGETS ${target} EXPORT raster-targets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
        RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
    endif()
  endif()
endfunction()
