// Whether this build runs under AddressSanitizer: g++ defines __SANITIZE_ADDRESS__,
// clang 14 (the instrumented build) answers __has_feature instead.
#pragma once

#if defined(__SANITIZE_ADDRESS__)
#define FSICONTACT_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define FSICONTACT_ASAN 1
#endif
#endif
