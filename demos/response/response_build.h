// A student's AddCollisionImpulse, from their file to a shared object the engine can call.
//
// The file is wrapped in a translation unit of ours: impulse/workshop.h first (the listing's
// types), then the file itself inside a namespace of its own (so that the listing's own
// `class RigidBody` can stand beside the header's), named by #line so that the compiler's
// messages give the student's file and line, then the entry point that fills the bodies in, calls
// AddCollisionImpulse and reads the velocities back (impulse/workshop_abi.h). $CXX (else c++)
// compiles it; the result is kept by the hash of everything that went into it in
//   $IMPULSE_RESPONSE_CACHE, else $XDG_CACHE_HOME/impulse/responses, else ~/.cache/impulse/responses,
// written as a temporary of its own and renamed, so concurrent builds of one file are safe.
#pragma once
#include <stdexcept>
#include <string>

namespace impulse::workshop {

// The file cannot be used: it is missing, it defines no AddCollisionImpulse, or it does not
// compile (what() then carries the compiler's messages as they are).
class BuildError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

// Where impulse/workshop.h is: $IMPULSE_WORKSHOP_INCLUDE, else beside the program
// (PREFIX/include for PREFIX/bin/impulse), else the source tree's.
std::string include_directory();
std::string cache_directory();

// The translation unit that wraps `text`, read from `source_path`.
std::string wrapper_source(const std::string& source_path, const std::string& text);

// The shared object for a response file: a .so as it is (checked when loaded), a .cpp (or .cc,
// .cxx, .c++) built, or taken from the cache when built before. `compiled` says which.
struct BuiltResponse {
  std::string shared_object;
  bool compiled = false;
};
BuiltResponse build_response(const std::string& source_path);

}  // namespace impulse::workshop
