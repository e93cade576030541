// [world] response = "FILE.cpp": a student's AddCollisionImpulse in place of listing 1's page
// (demos/response/). The path is the scene file's directory's, or, set from the command line
// (--response, --set, --vary), the current directory's. "reference" is the engine's own answer to
// the exercise: listing 1 corrected (physics/listing_reference.h), as a correct file would do it.
#pragma once
#include "demos/scene/scene.h"
#include "demos/scene/table_reader.h"

namespace impulse::demos {

// Reads the field of [world] (after `method`), builds the file (the compiler's errors are the
// field's) and sets scene.world.response, and the method to "workshop" when the table says none.
void read_response(TableReader& world_table, Scene& scene);

// The time each call of a response may take (s), for every scene read after: --time-limit.
void set_response_time_limit(double seconds);

}  // namespace impulse::demos
