#pragma once

// RASTER_TEST_ASAN is defined under the address sanitizer, which reserves terabytes of address
// space up front: tests that cap the address space (RLIMIT_AS) cannot run there.
#if defined(__SANITIZE_ADDRESS__)
#define RASTER_TEST_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define RASTER_TEST_ASAN 1
#endif
#endif
