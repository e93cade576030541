// The whole renderer in child processes under every llvmpipe setting a machine may run it with:
// vector width unset (the CPU's choice), 256 and 128 bits, each with 0, 1 and 2 rasteriser
// threads, all sharing one fresh shader cache in that order, so that a width reads shaders that
// another width compiled before it (the heap overflow of render/README.md, "Mesa's shader cache").
// A child that aborts, crashes or fails fails the test, whatever the machine's CPU.
#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

extern char** environ;

namespace impulse {
namespace {

namespace fs = std::filesystem;

struct Outcome {
  bool passed = false;
  std::string message;
};

// The test's environment, less every variable that steers llvmpipe or its cache, plus `settings`.
std::vector<std::string> child_environment(const std::vector<std::string>& settings) {
  const std::vector<std::string> steered = {"LP_NATIVE_VECTOR_WIDTH=", "LP_NUM_THREADS=", "MESA_SHADER_CACHE_DIR=",
                                            "MESA_SHADER_CACHE_DISABLE=", "MESA_GLSL_CACHE_DISABLE="};
  std::vector<std::string> environment;
  for (char** entry = environ; *entry != nullptr; ++entry) {
    const std::string variable = *entry;
    bool keep = true;
    for (const std::string& prefix : steered) keep = keep && variable.rfind(prefix, 0) != 0;
    if (keep) environment.push_back(variable);
  }
  environment.insert(environment.end(), settings.begin(), settings.end());
  return environment;
}

Outcome run_child(const std::vector<std::string>& settings, const fs::path& output) {
  fs::create_directories(output);
  const std::string program = IMPULSE_RENDER_EVERY_PROGRAM;
  const std::string output_text = output.string();
  const std::string log = (output / "stderr.txt").string();
  std::vector<std::string> environment = child_environment(settings);
  std::vector<char*> envp;
  for (std::string& variable : environment) envp.push_back(variable.data());
  envp.push_back(nullptr);
  char* argv[] = {const_cast<char*>(program.c_str()), const_cast<char*>(output_text.c_str()), nullptr};

  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  pid_t child = 0;
  const int spawn_error = posix_spawn(&child, program.c_str(), &actions, nullptr, argv, envp.data());
  posix_spawn_file_actions_destroy(&actions);
  if (spawn_error != 0) return {false, "cannot start " + program + ": " + std::strerror(spawn_error)};
  int status = 0;
  if (waitpid(child, &status, 0) != child) return {false, "waitpid failed"};

  std::ostringstream said;
  said << std::ifstream(log).rdbuf();
  if (WIFEXITED(status) && WEXITSTATUS(status) == 0) return {true, ""};
  std::string how = WIFSIGNALED(status) ? std::string("killed by ") + strsignal(WTERMSIG(status))
                                        : "exit code " + std::to_string(WEXITSTATUS(status));
  return {false, how + "; stderr: " + said.str()};
}

TEST(RenderChildren, EveryProgramAtEveryVectorWidthAndThreadCount) {
  const fs::path work = fs::temp_directory_path() / ("impulse_render_children_" + std::to_string(getpid()));
  fs::remove_all(work);
  const std::string cache = "MESA_SHADER_CACHE_DIR=" + (work / "shader_cache").string();
  fs::create_directories(work / "shader_cache");
  // Unset and 256 first: they fill the cache that 128 then reads.
  for (const std::string width : {"", "256", "128"}) {
    for (const std::string threads : {"0", "1", "2"}) {
      std::vector<std::string> settings = {cache, "LP_NUM_THREADS=" + threads};
      if (!width.empty()) settings.push_back("LP_NATIVE_VECTOR_WIDTH=" + width);
      const std::string name = "width_" + (width.empty() ? std::string("unset") : width) + "_threads_" + threads;
      const Outcome outcome = run_child(settings, work / name);
      EXPECT_TRUE(outcome.passed) << name << ": " << outcome.message;
      for (const char* video : {"impostors_ground_shadows.mp4", "icospheres_shadow_map.mp4"}) {
        EXPECT_GT(fs::exists(work / name / video) ? fs::file_size(work / name / video) : 0u, 1000u)
            << name << ": " << video;
      }
    }
  }
  if (!::testing::Test::HasFailure()) fs::remove_all(work);
}

}  // namespace
}  // namespace impulse
