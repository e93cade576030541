#include "demos/scene/scene_response.h"

#include "demos/response/response_build.h"
#include "demos/response/response_child.h"

#include <atomic>
#include <filesystem>

namespace fs = std::filesystem;

namespace impulse::demos {

namespace {
std::atomic<double> time_limit{workshop::kDefaultTimeLimit};
}  // namespace

void set_response_time_limit(double seconds) { time_limit = seconds; }

void read_response(TableReader& r, Scene& scene) {
  if (!r.has("response")) return;
  const toml::node* node = r.get("response");
  const std::string value = r.string("response", "reference");
  if (value == "reference") {  // the engine's own answer: listing 1 corrected (physics/listing_reference.h)
    if (r.has("method") && scene.world.method != physics::ResponseMethod::workshop)
      r.fail(node, "response", "\"reference\" is listing 1 corrected, the workshop method's page: set method = \"workshop\", or leave it out");
    if (scene.world.printed_eq8_sign)
      r.fail(node, "response", "\"reference\" is listing 1 corrected, with eq. 8's 1 + e: leave eq8_sign out");
    scene.world.method = physics::ResponseMethod::workshop;
    scene.world.reference_listing = true;
    return;
  }
  if (value.empty()) r.fail(node, "response", "give a C++ file defining AddCollisionImpulse, or \"reference\" for the engine's own");
  if (r.has("method") && scene.world.method != physics::ResponseMethod::workshop)
    r.fail(node, "response",
           "a response takes the place of listing 1's page, so it runs with method = \"workshop\": set that, or leave method out");
  if (scene.world.printed_eq8_sign)
    r.fail(node, "response", "eq8_sign = \"printed\" is listing 1's own page's: a response has its own sign (leave eq8_sign out)");
  // From the file: beside the scene. From the command line (its node has no source in the file):
  // where the user is, or else beside the scene (a [compare] table's values come as --set does).
  const bool from_file = node->source().path && *node->source().path == scene.path;
  const fs::path beside = fs::path(scene.path).parent_path() / value;
  const bool relative = fs::path(value).is_relative();
  const fs::path path = relative && (from_file || (!fs::exists(value) && fs::exists(beside))) ? beside : fs::path(value);
  try {
    const workshop::BuiltResponse built = workshop::build_response(path.string());
    scene.world.response = workshop::child_response_maker(built.shared_object, path.string(), time_limit);
  } catch (const workshop::BuildError& error) {
    r.fail(node, "response", error.what());
  }
  scene.world.method = physics::ResponseMethod::workshop;
}

}  // namespace impulse::demos
