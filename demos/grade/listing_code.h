// Where a student's file holds listing 1's own code, by line, so that a hint names that line of
// the student's file, and only when the file has it (a hint that blames "line 85's hack fix" in a
// file without one sends the student looking for what is not there).
#pragma once
#include <string>

namespace impulse::workshop {

// The line (from 1) of `source` that adds the penetration, times a number, to the normal impulse:
// the listing's "hack fix", jn = jn + (penetration*1.5f) (its line 85), in C++ or Python; 0 where
// none does. A correction through a division (by normDiv, by the time step) is not that.
int hack_fix_line(const std::string& source);

}  // namespace impulse::workshop
