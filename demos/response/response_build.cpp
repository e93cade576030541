#include "demos/response/response_build.h"

#include "demos/response/compile_sandbox.h"
#include "demos/response/include_check.h"
#include "demos/response/precompiled_header.h"
#include "demos/response/sandbox_limits.h"
#include "tex/tex_cache.h"

#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>
#include <sstream>
#include <vector>

namespace fs = std::filesystem;

namespace impulse::workshop {

namespace {

std::string read_text(const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  if (!file) throw BuildError(path + ": cannot read the response file (does it exist?)");
  std::ostringstream text;
  text << file.rdbuf();
  return text.str();
}

std::string executable_directory() {
  std::error_code error;
  const fs::path self = fs::read_symlink("/proc/self/exe", error);
  return error ? std::string() : self.parent_path().string();
}

// A file name as a string literal for #line: backslashes and quotes escaped.
std::string quoted(const std::string& text) {
  std::string out = "\"";
  for (const char c : text) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + "\"";
}

std::string compiler_name() {
  const char* cxx = std::getenv("CXX");
  return cxx != nullptr && *cxx != '\0' ? cxx : "c++";
}

// The compiler's path, looked up in PATH as a shell would.
std::string compiler_path(const std::string& name) {
  if (name.find('/') != std::string::npos) return name;
  const char* search = std::getenv("PATH");
  std::stringstream directories(search ? search : "/usr/bin:/bin");
  for (std::string directory; std::getline(directories, directory, ':');)
    if (!directory.empty() && access((directory + "/" + name).c_str(), X_OK) == 0) return directory + "/" + name;
  return name;
}

// What identifies the compiler without running it: its resolved path, size and time.
std::string compiler_identity(const std::string& path) {
  std::error_code error;
  const fs::path real = fs::canonical(path, error);
  struct stat info {};
  if (error || stat(real.c_str(), &info) != 0) return path;
  return real.string() + " " + std::to_string(info.st_size) + " " + std::to_string(info.st_mtime);
}

bool is_clang(const std::string& path) {
  std::error_code error;
  const fs::path real = fs::canonical(path, error);
  return (error ? fs::path(path) : real).filename().string().find("clang") != std::string::npos;
}

std::string head_of(const std::string& path, long bytes) {
  std::ifstream file(path, std::ios::binary);
  std::string text(size_t(bytes), '\0');
  file.read(text.data(), bytes);
  text.resize(size_t(file.gcount()));
  return text;
}

// Why a compile that did not succeed failed, in words: a limit it passed, or its messages (the
// first of them) when the file does not compile.
std::string compile_failure(const std::string& source_path, const tex::ChildOutcome& outcome, const std::string& messages, bool cut) {
  const auto says = [&messages](const char* text) { return messages.find(text) != std::string::npos; };
  const std::string limit = ", which a build may not: a template that instantiates itself without end?";
  if (outcome.timed_out)
    return source_path + ": the compiler was still at it after " + std::to_string(int(limits::kCompileSeconds)) + " s" + limit;
  if (outcome.signal == SIGXCPU || says("CPU time limit exceeded"))
    return source_path + ": the compiler used more than " + std::to_string(limits::kCompileCpuSeconds) + " s of processor time" + limit;
  if (outcome.signal == SIGXFSZ || says("File size limit exceeded"))
    return source_path + ": the compiler wrote more than " + limits::size_words(limits::kCompileFileBytes) + limit;
  if (says("memory exhausted") || says("out of memory") || says("Cannot allocate memory") || says("std::bad_alloc"))
    return source_path + ": the compiler needed more than the " + limits::size_words(limits::kCompileMemoryBytes) + " of memory" + limit;
  return source_path + " does not compile:\n" + messages + (cut ? "\n(the compiler's further messages are not shown)\n" : "");
}

// The entry point, after the student's file, in its namespace: RigidBody and AddCollisionImpulse
// are the student's own where the file declares them, else the header's RigidBody. Members the
// student's RigidBody lacks are left out.
constexpr const char* kEntryPoint = R"(
template <class V> void impulse_put(V& v, const float* a) { v.x = a[0]; v.y = a[1]; v.z = a[2]; }
template <class V> void impulse_get(const V& v, float* a) { a[0] = v.x; a[1] = v.y; a[2] = v.z; }
template <class M> void impulse_put_matrix(M& m, const float* rows, const float* fourth_row) {
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) m.m[r][c] = r < 3 && c < 3 ? rows[3 * r + c] : r == 3 && c < 3 ? fourth_row[c] : r == c ? 1.0f : 0.0f;
}
template <class Body> void impulse_fill(Body& b, const impulse_workshop_body& p) {
  const float origin[3] = {0, 0, 0};
  if constexpr (requires { b.m_centre; }) impulse_put(b.m_centre, p.centre);
  if constexpr (requires { b.m_invMass; }) b.m_invMass = p.inv_mass;
  if constexpr (requires { b.m_linVelocity; }) impulse_put(b.m_linVelocity, p.lin_velocity);
  if constexpr (requires { b.m_forces; }) impulse_put(b.m_forces, p.forces);
  if constexpr (requires { b.m_invInertia; }) impulse_put_matrix(b.m_invInertia, p.inv_inertia, origin);
  if constexpr (requires { b.m_angVelocity; }) impulse_put(b.m_angVelocity, p.ang_velocity);
  if constexpr (requires { b.m_orientation; }) {
    b.m_orientation.w = p.orientation[0]; b.m_orientation.x = p.orientation[1];
    b.m_orientation.y = p.orientation[2]; b.m_orientation.z = p.orientation[3];
  }
  if constexpr (requires { b.m_torques; }) impulse_put(b.m_torques, p.torques);
  if constexpr (requires { b.m_matWorld; }) {  // row vectors: the rows are the body's axes in the world
    const float w = p.orientation[0], x = p.orientation[1], y = p.orientation[2], z = p.orientation[3];
    const float axes[9] = {1 - 2 * (y * y + z * z), 2 * (x * y + w * z),     2 * (x * z - w * y),
                           2 * (x * y - w * z),     1 - 2 * (x * x + z * z), 2 * (y * z + w * x),
                           2 * (x * z + w * y),     2 * (y * z - w * x),     1 - 2 * (x * x + y * y)};
    impulse_put_matrix(b.m_matWorld, axes, p.centre);
  }
  if constexpr (requires { b.m_worldInvInertia; }) impulse_put_matrix(b.m_worldInvInertia, p.world_inv_inertia, origin);
  if constexpr (requires { b.m_restitution; }) b.m_restitution = p.restitution;
  if constexpr (requires { b.m_friction; }) b.m_friction = p.friction;
}
template <class Body> void impulse_read(const Body& b, impulse_workshop_body& p) {
  if constexpr (requires { b.m_linVelocity; }) impulse_get(b.m_linVelocity, p.lin_velocity);
  if constexpr (requires { b.m_angVelocity; }) impulse_get(b.m_angVelocity, p.ang_velocity);
}

extern "C" __attribute__((visibility("default"))) int impulse_workshop_abi_version() { return IMPULSE_WORKSHOP_ABI_VERSION; }

extern "C" __attribute__((visibility("default"))) int impulse_workshop_respond(
    impulse_workshop_body* p0, impulse_workshop_body* p1, const impulse_workshop_contact* contact, char* message, int size) {
  try {
    ::impulse_workshop::time_step = contact->time_step;
    RigidBody c0, c1;
    impulse_fill(c0, *p0);
    impulse_fill(c1, *p1);
    const Vector3 hitPoint(contact->point[0], contact->point[1], contact->point[2]);
    const Vector3 normal(contact->normal[0], contact->normal[1], contact->normal[2]);
    AddCollisionImpulse(c0, c1, hitPoint, normal, contact->penetration);
    impulse_read(c0, *p0);
    impulse_read(c1, *p1);
    return 0;
  } catch (const ::impulse_workshop::NotFinite& error) {
    std::snprintf(message, size_t(size), "%s", error.what());
  } catch (const std::exception& error) {
    std::snprintf(message, size_t(size), "AddCollisionImpulse threw an exception: %s", error.what());
  } catch (...) {
    std::snprintf(message, size_t(size), "AddCollisionImpulse threw an exception");
  }
  return 1;
}
)";

}  // namespace

std::string include_directory() {
  if (const char* own = std::getenv("IMPULSE_WORKSHOP_INCLUDE"); own != nullptr && *own != '\0') return own;
  const fs::path beside = fs::path(executable_directory()).parent_path() / "include";
  if (!executable_directory().empty() && fs::exists(beside / "impulse" / "workshop.h")) return beside.string();
  return IMPULSE_WORKSHOP_INCLUDE_DIR;
}

std::string cache_directory() {
  if (const char* own = std::getenv("IMPULSE_RESPONSE_CACHE"); own != nullptr && *own != '\0') return own;
  if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg != nullptr && *xdg == '/') return std::string(xdg) + "/impulse/responses";
  if (const char* home = std::getenv("HOME"); home != nullptr && *home != '\0') return std::string(home) + "/.cache/impulse/responses";
  return (fs::temp_directory_path() / ("impulse-responses-" + std::to_string(getuid()))).string();
}

// The student's #include <...> lines (and of the workshop header) go before the namespace, each
// under a #line of its own: a standard header cannot be included inside a namespace. The line
// stays, empty, so that every other line keeps its number.
std::string wrapper_source(const std::string& source_path, const std::string& text) {
  const std::string file = quoted(fs::absolute(source_path).lexically_normal().string());
  std::string includes, body;
  std::istringstream lines(text);
  int number = 0;
  for (std::string line; std::getline(lines, line);) {
    ++number;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (is_hoisted_include(line)) {
      includes += "#line " + std::to_string(number) + " " + file + "\n" + line + "\n";
      body += "\n";
    } else {
      body += line + "\n";
    }
  }
  return "// impulse's translation unit for " + file + ": the workshop header, the file, the entry point.\n"
         "#include \"impulse/workshop.h\"\n" +
         includes + "namespace impulse_student {\n#line 1 " + file + "\n" + body +
         "#line 1 \"impulse's call of AddCollisionImpulse(c0, c1, hitPoint, normal, penetration)\"\n" + kEntryPoint +
         "}  // namespace impulse_student\n";
}

BuiltResponse build_response(const std::string& source_path) {
  const std::string extension = fs::path(source_path).extension().string();
  if (extension == ".so") {
    if (!fs::is_regular_file(source_path)) throw BuildError(source_path + ": no such shared object");
    return {fs::absolute(source_path).string(), false};
  }
  if (extension != ".cpp" && extension != ".cc" && extension != ".cxx" && extension != ".c++")
    throw BuildError(source_path + ": a response is a C++ file (.cpp) defining AddCollisionImpulse, or a .so built from one by "
                                   "`impulse response FILE.cpp -o FILE.so`");
  if (fs::is_symlink(source_path))
    throw BuildError(source_path + ": is a symbolic link: a response file is read as it is, never through a link");
  const std::string text = read_text(source_path);
  if (text.find("AddCollisionImpulse") == std::string::npos)
    throw BuildError(source_path + ": defines no AddCollisionImpulse: write listing 1's static void AddCollisionImpulse(RigidBody& c0, "
                                   "RigidBody& c1, const Vector3& hitPoint, const Vector3& normal, float penetration)");
  if (const std::optional<std::string> refused = refused_in_source(source_path, text)) throw BuildError(*refused);

  const std::string include = include_directory(), compiler = compiler_path(compiler_name());
  const bool clang = is_clang(compiler);
  const std::string source = wrapper_source(source_path, text);
  const std::vector<std::string> flags = {"-std=c++20", "-O2", "-fPIC", "-shared", "-fvisibility=hidden", "-ffp-contract=off",
                                          (clang ? "-ferror-limit=" : "-fmax-errors=") + std::to_string(limits::kCompileErrors)};
  std::string identity = compiler_identity(compiler) + "\n" + read_text(include + "/impulse/workshop.h") +
                         read_text(include + "/impulse/workshop_abi.h") + source;
  for (const std::string& flag : flags) identity += "\n" + flag;
  const std::string directory = cache_directory();
  const std::string shared_object = directory + "/" + tex::text_hash(identity) + ".so";
  if (fs::is_regular_file(shared_object)) return {shared_object, false};

  // A build directory of its own, the only place the compiler may write.
  std::error_code error;
  fs::create_directories(directory, error);
  static std::atomic<unsigned> counter{0};
  const fs::path build = fs::absolute(shared_object + "." + std::to_string(getpid()) + "-" + std::to_string(counter++) + ".d");
  fs::remove_all(build, error);
  if (!fs::create_directory(build, error)) throw BuildError("cannot make " + build.string() + " (set IMPULSE_RESPONSE_CACHE to a directory you can write)");
  const std::string wrapper = (build / "response.cpp").string(), built = (build / "response.so").string(), log = (build / "compiler.log").string();
  {
    std::ofstream out(wrapper, std::ios::binary);
    out << source;
    if (!out.flush()) throw BuildError("cannot write " + wrapper + " (set IMPULSE_RESPONSE_CACHE to a directory you can write)");
  }
  CompileJob job;
  job.readable = {include, fs::absolute(source_path).lexically_normal().string()};
  job.argv = {compiler};
  job.argv.insert(job.argv.end(), flags.begin(), flags.end());
  for (const std::string& flag : header_flags(compiler, compiler_identity(compiler), clang, flags, include, directory, job.readable))
    job.argv.push_back(flag);
  job.argv.insert(job.argv.end(), {"-o", built, wrapper});
  job.build_directory = build.string();
  job.log_path = log;
  job.toolchain_list = directory + "/toolchain-" + tex::text_hash(compiler_identity(compiler)) + ".txt";
  const tex::ChildOutcome outcome = run_compiler(job);
  const std::string messages = head_of(log, limits::kShownCompileBytes);
  const bool cut = fs::file_size(log, error) > uintmax_t(messages.size());
  if (outcome.started && !outcome.timed_out && outcome.exit_code == 0) fs::rename(built, shared_object, error);
  const bool renamed = !error;
  fs::remove_all(build, error);
  if (!outcome.started) throw BuildError("cannot run the C++ compiler " + compiler + ": " + outcome.error + " (install g++, or set CXX)");
  if (outcome.timed_out || outcome.exit_code != 0) throw BuildError(compile_failure(source_path, outcome, messages, cut));
  if (!messages.empty()) std::fputs(messages.c_str(), stderr);  // its warnings, as they are
  if (!renamed) throw BuildError("cannot write " + shared_object);
  return {shared_object, true};
}

}  // namespace impulse::workshop
