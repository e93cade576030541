#include "demos/response/precompiled_header.h"

#include "demos/response/compile_sandbox.h"
#include "tex/tex_cache.h"

#include <unistd.h>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace fs = std::filesystem;

namespace impulse::workshop {

namespace {

std::string text_of(const fs::path& path) {
  std::ifstream file(path, std::ios::binary);
  std::ostringstream text;
  text << file.rdbuf();
  return text.str();
}

// The directory with the PCH, made if need be; empty when it cannot be made.
std::string precompiled(const std::string& compiler, const std::string& compiler_identity, bool clang,
                        const std::vector<std::string>& flags, const std::string& include, const std::string& cache,
                        const std::string& identity) {
  const fs::path done = fs::path(cache) / ("pch-" + tex::text_hash(identity));
  const std::string pch_name = clang ? "workshop.h.pch" : "workshop.h.gch";
  if (fs::is_regular_file(done / "impulse" / pch_name)) return done.string();
  static std::atomic<unsigned> counter{0};
  const fs::path work = done.string() + "." + std::to_string(getpid()) + "-" + std::to_string(counter++) + ".tmp";
  std::error_code error;
  fs::remove_all(work, error);
  fs::create_directories(work / "impulse", error);
  for (const char* header : {"workshop.h", "workshop_abi.h"}) fs::copy_file(fs::path(include) / "impulse" / header, work / "impulse" / header, error);
  CompileJob job;
  job.argv = {compiler};
  for (const std::string& flag : flags)
    if (flag != "-shared") job.argv.push_back(flag);
  job.argv.insert(job.argv.end(), {"-I" + work.string(), "-x", "c++-header", (work / "impulse/workshop.h").string(), "-o",
                                   (work / "impulse" / pch_name).string()});
  job.build_directory = work.string();
  job.log_path = (work / "compiler.log").string();
  job.toolchain_list = (fs::path(cache) / ("toolchain-" + tex::text_hash(compiler_identity) + ".txt")).string();
  const tex::ChildOutcome outcome = error ? tex::ChildOutcome{} : run_compiler(job);
  fs::remove(job.log_path, error);
  // Another process may have made it meanwhile: then the rename fails and theirs is used.
  if (outcome.started && !outcome.timed_out && outcome.exit_code == 0) fs::rename(work, done, error);
  fs::remove_all(work, error);
  return fs::is_regular_file(done / "impulse" / pch_name) ? done.string() : "";
}

}  // namespace

std::vector<std::string> header_flags(const std::string& compiler, const std::string& compiler_identity, bool clang,
                                      const std::vector<std::string>& flags, const std::string& include, const std::string& cache,
                                      std::vector<std::string>& readable) {
  std::string identity = compiler_identity + "\n" + text_of(fs::path(include) / "impulse/workshop.h") + text_of(fs::path(include) / "impulse/workshop_abi.h");
  for (const std::string& flag : flags) identity += "\n" + flag;
  const std::string directory = precompiled(compiler, compiler_identity, clang, flags, include, cache, identity);
  if (directory.empty()) return {"-I" + include};
  readable.push_back(directory);
  if (clang) return {"-include-pch", directory + "/impulse/workshop.h.pch", "-I" + directory};
  return {"-include", "impulse/workshop.h", "-I" + directory};
}

}  // namespace impulse::workshop
