// The whole renderer in child processes under every llvmpipe setting a machine may run it with:
// vector width unset (the CPU's choice), 256 and 128 bits, each with 0, 1 and 2 rasteriser
// threads, all sharing one fresh shader cache in that order, so that a width reads shaders that
// another width compiled before it (the heap overflow of render/README.md, "Mesa's shader cache and the vector width").
// A child that aborts, crashes or fails fails the test, whatever the machine's CPU.
#include <unistd.h>

#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "tests/support/child_process.h"

namespace impulse {
namespace {

namespace fs = std::filesystem;

TEST(RenderChildren, EveryProgramAtEveryVectorWidthAndThreadCount) {
  const fs::path work = fs::temp_directory_path() / ("impulse_render_children_" + std::to_string(getpid()));
  fs::remove_all(work);
  fs::create_directories(work / "shader_cache");
  // Unset and 256 first: they fill the cache that 128 then reads.
  for (const std::string width : {"", "256", "128"}) {
    for (const std::string threads : {"0", "1", "2"}) {
      testing::ChildSettings settings;
      settings.unset = {"LP_NATIVE_VECTOR_WIDTH", "LP_NUM_THREADS", "MESA_SHADER_CACHE_DIR",
                        "MESA_SHADER_CACHE_DISABLE", "MESA_GLSL_CACHE_DISABLE"};
      settings.set = {"MESA_SHADER_CACHE_DIR=" + (work / "shader_cache").string(), "LP_NUM_THREADS=" + threads};
      if (!width.empty()) settings.set.push_back("LP_NATIVE_VECTOR_WIDTH=" + width);
      const std::string name = "width_" + (width.empty() ? std::string("unset") : width) + "_threads_" + threads;
      const fs::path output = work / name;
      fs::create_directories(output);
      const testing::ChildResult result = testing::run_child({IMPULSE_RENDER_EVERY_PROGRAM, output.string()}, settings);
      EXPECT_TRUE(result.succeeded()) << name << ": " << result.describe();
      for (const char* video : {"impostors_ground_shadows.mp4", "icospheres_shadow_map.mp4"}) {
        EXPECT_GT(fs::exists(output / video) ? fs::file_size(output / video) : 0u, 1000u) << name << ": " << video;
      }
    }
  }
  if (!::testing::Test::HasFailure()) fs::remove_all(work);
}

}  // namespace
}  // namespace impulse
