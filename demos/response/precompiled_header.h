// The student's header, impulse/workshop.h, precompiled once per compiler, flags and header text,
// and kept in the response cache: it includes most of the standard library (for the students'
// convenience), whose parsing is most of a response's compile (GCC 12 at -O2: 1.2 s of 1.4;
// with the header precompiled, 0.4). A directory holds the two headers and the PCH beside them:
// GCC finds impulse/workshop.h.gch where it looks for the header, clang is given -include-pch.
// Made by the compiler under the same sandbox as a student's file (compile_sandbox.h), written
// whole or not at all; a compile without it gives the same shared object, only slower.
#pragma once
#include <string>
#include <vector>

namespace impulse::workshop {

// The flags that make a compile with `flags` by `compiler` (`identity`: its path, size and time)
// find impulse/workshop.h, precompiled when it can be: "-include impulse/workshop.h -IDIR" (GCC) or
// "-include-pch DIR/impulse/workshop.h.pch -IDIR" (clang), else "-IINCLUDE". `readable` gets the
// directory a compile must be let read.
std::vector<std::string> header_flags(const std::string& compiler, const std::string& identity, bool clang,
                                      const std::vector<std::string>& flags, const std::string& include, const std::string& cache,
                                      std::vector<std::string>& readable);

}  // namespace impulse::workshop
