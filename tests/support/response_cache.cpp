// The response and grade tests build responses into a cache of their own, under the build
// directory, and never into the user's.
#include <cstdlib>

namespace {
const bool cache_chosen = [] { return setenv("IMPULSE_RESPONSE_CACHE", IMPULSE_TEST_SCRATCH "/response_cache", 1) == 0; }();
}  // namespace
