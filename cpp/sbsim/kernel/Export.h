#pragma once

// libsbsim is built with hidden symbols: only what is marked SBSIM_API — the classes the program,
// service plugins and other code outside the library use — is exported. That keeps the library's
// symbol table small and lets calls inside it bind directly.
#if defined(__GNUC__) || defined(__clang__)
#define SBSIM_API __attribute__((visibility("default")))
#else
#define SBSIM_API
#endif
