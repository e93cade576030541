// What a student's code may use, at compile time and when it runs: the numbers the sandbox sets
// (README.md here, "The sandbox"), and the reports quote.
#pragma once
#include <sys/resource.h>

#include <string>

namespace impulse::workshop::limits {

// impulse-respond, the process that runs the student's code: its rlimits, in force before the
// shared object is loaded (its constructors included).
inline constexpr rlim_t kMemoryBytes = rlim_t(512) << 20;  // RLIMIT_AS: address space, the code's and its heap's
inline constexpr rlim_t kCpuSeconds = 120;  // RLIMIT_CPU: the backstop when impulse is gone mid-call (calls are timed)
inline constexpr rlim_t kOpenFiles = 8;     // RLIMIT_NOFILE: 0-3 are open, the shared object takes one while loading
// Bytes it may print (standard output and error, in all): past it the process is stopped.
inline constexpr long kOutputBytes = long(1) << 20;
inline constexpr long kShownOutputBytes = long(64) << 10;  // what of that impulse copies to its standard error

// The compiler: each of its processes (the driver, cc1plus, as, ld) gets these rlimits.
inline constexpr rlim_t kCompileMemoryBytes = rlim_t(1) << 30;  // RLIMIT_AS (<bits/stdc++.h> at -O2: 240 MB)
inline constexpr rlim_t kCompileCpuSeconds = 60;                // RLIMIT_CPU
inline constexpr double kCompileSeconds = 60;                   // on the clock, for all of it
inline constexpr rlim_t kCompileFileBytes = rlim_t(64) << 20;   // RLIMIT_FSIZE: its messages, temporaries, the .so
inline constexpr int kCompileErrors = 10;                       // -fmax-errors / -ferror-limit
inline constexpr long kShownCompileBytes = long(16) << 10;      // of its messages, shown

// A size in words: "512 MiB", "1 GiB", "64 KiB" (whole units, as the limits are).
inline std::string size_words(unsigned long long bytes) {
  const char* units[] = {"bytes", "KiB", "MiB", "GiB"};
  int unit = 0;
  while (unit < 3 && bytes >= 1024 && bytes % 1024 == 0) {
    bytes /= 1024;
    ++unit;
  }
  return std::to_string(bytes) + " " + units[unit];
}

}  // namespace impulse::workshop::limits
