// The hostile battery (hostile/README.md): each file of hostile/run tried from AddCollisionImpulse
// and from a constructor, each of hostile/compile handed to the compiler, through `impulse grade`
// as a course's autograder runs it: as this user, and again as nobody when this is root (CI runs
// as root). Each must be stopped and reported in its words, the grade's exit code that of a failed
// case (2) or of a file that does not compile (1), nothing written to the scratch folder, no
// connection made to the test's port, no line of /etc/passwd shown. The runs are bounded from
// outside (the file's own loops, 4 GiB of address space for impulse-respond, 120 s on the clock),
// so that a sandbox that fails makes the test fail, never the machine.
#include "demos/response/respond_protocol.h"
#include "tests/support/child_process.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <arpa/inet.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <tuple>

namespace impulse::workshop {
namespace {

namespace fs = std::filesystem;

constexpr uid_t kNobody = 65534;

struct User {
  std::string name;
  bool as_nobody = false;
};

// This user; and nobody, when this is root.
std::vector<User> users() {
  std::vector<User> list = {{geteuid() == 0 ? "root" : "this user"}};
  if (geteuid() == 0) list.push_back({"nobody", true});
  return list;
}

std::string text_of(const fs::path& path) {
  std::ifstream file(path);
  std::ostringstream text;
  text << file.rdbuf();
  return text.str();
}

void replace_all(std::string& text, const std::string& what, const std::string& with) {
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + with.size())) text.replace(at, what.size(), with);
}

// Written whole, with its permissions, or not at all: two tests may write and run the same file at once.
void write_file(const fs::path& path, const std::string& text,
                fs::perms permissions = fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read | fs::perms::others_read) {
  const fs::path part = path.string() + "." + std::to_string(getpid()) + ".part";
  std::ofstream(part) << text;
  fs::permissions(part, permissions);
  fs::rename(part, path);
}

// A folder that nobody may write too, so that a write the sandbox let through would land.
fs::path open_folder(const fs::path& path) {
  fs::create_directories(path);
  fs::permissions(path, fs::perms::all);
  return path;
}

fs::path battery_directory() { return open_folder(fs::path(IMPULSE_TEST_SCRATCH) / "hostile"); }

// impulse-respond under an outer limit of 4 GiB of address space: what a sandbox that failed could use.
fs::path bounded_responder() {
  const fs::path script = battery_directory() / "bounded-impulse-respond";
  write_file(script, "#!/bin/sh\nulimit -v 4194304\nexec '" + fs::path(IMPULSE_PROGRAM).parent_path().string() + "/impulse-respond' \"$@\"\n",
             fs::perms::owner_all | fs::perms::group_read | fs::perms::group_exec | fs::perms::others_read | fs::perms::others_exec);
  return script;
}

struct Outcome {
  ::impulse::testing::ChildResult result;
  std::string out;  // its standard output
};

// `impulse ARGS` as `user`, with the battery's cache and the bounded responder, 120 s at most.
Outcome impulse_as(const User& user, const std::vector<std::string>& arguments) {
  static const fs::path responder = bounded_responder();
  const fs::path out = battery_directory() / ("out." + std::to_string(getpid()) + ".txt");
  const auto quoted = [](const std::string& word) { return std::string(1, '\'').append(word).append(1, '\''); };
  std::string command = "exec timeout -s KILL 120 ";
  if (user.as_nobody) command += "setpriv --reuid=" + std::to_string(kNobody) + " --regid=" + std::to_string(kNobody) + " --clear-groups ";
  command += quoted(IMPULSE_PROGRAM);
  for (const std::string& argument : arguments) command.append(1, ' ').append(quoted(argument));
  command.append(" > ").append(quoted(out.string()));
  ::impulse::testing::ChildSettings settings;
  settings.set = {"IMPULSE_RESPONSE_CACHE=" + open_folder(battery_directory() / "cache").string(), "IMPULSE_RESPOND=" + responder.string()};
  Outcome run{::impulse::testing::run_child({"/bin/sh", "-c", command}, settings), text_of(out)};
  fs::remove(out);
  return run;
}

// The things a sandbox that failed would have shown.
void expect_nothing_leaked(const Outcome& run, const std::string& who) {
  for (const char* sign : {"root:x:0:0", "read: ", "listed: "}) {
    EXPECT_EQ(run.out.find(sign), std::string::npos) << who << ": " << run.out;
    EXPECT_EQ(run.result.stderr_text.find(sign), std::string::npos) << who << ": " << run.result.stderr_text;
  }
}

// A TCP port on 127.0.0.1 that the test listens on, to see whether anything connected.
class Listener {
 public:
  Listener() : fd_(socket(AF_INET, SOCK_STREAM | SOCK_NONBLOCK | SOCK_CLOEXEC, 0)) {
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    socklen_t size = sizeof address;
    if (bind(fd_, reinterpret_cast<sockaddr*>(&address), size) != 0 || listen(fd_, 16) != 0 ||
        getsockname(fd_, reinterpret_cast<sockaddr*>(&address), &size) != 0)
      throw std::runtime_error("cannot listen on 127.0.0.1");
    port_ = ntohs(address.sin_port);
  }
  ~Listener() { close(fd_); }
  Listener(const Listener&) = delete;
  Listener& operator=(const Listener&) = delete;

  int port() const { return port_; }
  bool connected() const {
    const int connection = accept(fd_, nullptr, nullptr);
    if (connection >= 0) close(connection);
    return connection >= 0;
  }

 private:
  int fd_;
  int port_ = 0;
};

// What each file of hostile/run must be reported as, after "FILE: WHO " (WHO: the function, or
// the loading of the shared object); SCRATCH is its scratch folder.
std::string expected_report(const std::string& name, bool in_constructor, const std::string& scratch) {
  const std::string refused = ", which graded code may not do";
  const std::map<std::string, std::string> reports = {
      {"read_file", "tried to open a file ('/etc/passwd')" + refused},
      {"write_file", "tried to write a file ('" + scratch + "/written.txt')" + refused},
      {"list_directory", "tried to list a directory ('" + scratch + "')" + refused},
      {"socket", "tried to open a network socket" + refused},
      {"shell", "tried to start a process (fork, system() or a thread)" + refused},
      {"fork_loop", "tried to start a process (fork, system() or a thread)" + refused},
      {"allocate", "used more memory than graded code may (its limit is 512 MiB)"},
      {"spin", in_constructor ? "did not end within 3.5 s: an endless loop?" : "did not return within 0.5 s: an endless loop?"},
      {"million_lines", "printed more than 1 MiB (a print in a loop?)" + refused},
  };
  return std::string(in_constructor ? kLoaderWords : kCallerWords) + " " + reports.at(name);
}

std::vector<std::string> files_in(const std::string& folder) {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(fs::path(IMPULSE_SOURCE_DIR) / "tests/response/hostile" / folder))
    if (entry.path().extension() == ".cpp") names.push_back(entry.path().stem().string());
  std::sort(names.begin(), names.end());
  return names;
}

using RunCase = std::tuple<std::string, bool>;  // a file of hostile/run; from a constructor

class HostileRun : public ::testing::TestWithParam<RunCase> {};

TEST_P(HostileRun, IsStoppedAndReported) {
  const auto& [name, in_constructor] = GetParam();
  const std::string mode = in_constructor ? "constructor" : "call";
  const fs::path scratch = open_folder(battery_directory() / (name + "_" + mode + ".scratch"));
  const Listener listener;
  std::string text = text_of(fs::path(IMPULSE_SOURCE_DIR) / "tests/response/hostile/run" / (name + ".cpp"));
  replace_all(text, "@SCRATCH@", scratch.string());
  replace_all(text, "@PORT@", std::to_string(listener.port()));
  const std::string signature = "(RigidBody& c0, RigidBody& c1, const Vector3& hitPoint, const Vector3& normal, float penetration)";
  text += in_constructor ? "__attribute__((constructor)) static void Early() { Hostile(); }\nstatic void AddCollisionImpulse" + signature + " {}\n"
                         : "static void AddCollisionImpulse" + signature + " { Hostile(); }\n";
  // The port is the listener's, so the file is this run's own.
  const fs::path file = battery_directory() / (name + "_" + mode + "_" + std::to_string(listener.port()) + ".cpp");
  write_file(file, text);
  for (const User& user : users()) {
    fs::remove_all(scratch);
    open_folder(scratch);
    // A short limit for the file that spins; time enough for the others to reach their limit.
    const Outcome run = impulse_as(user, {"grade", file.string(), "--only", "head_on_equal_e1", "--time-limit", name == "spin" ? "0.5" : "20", "--json"});
    EXPECT_EQ(run.result.exit_code, 2) << user.name << ": " << run.result.describe();
    const nlohmann::json grade = nlohmann::json::parse(run.out, nullptr, false);
    ASSERT_FALSE(grade.is_discarded()) << user.name << ": " << run.out << run.result.describe();
    const std::string failure = grade["cases"][0]["failure"];
    EXPECT_NE(failure.find(file.string() + ": " + expected_report(name, in_constructor, scratch.string())), std::string::npos)
        << user.name << ": " << failure;
    expect_nothing_leaked(run, user.name);
    EXPECT_TRUE(fs::is_empty(scratch)) << user.name << ": something was written in " << scratch;
    EXPECT_FALSE(listener.connected()) << user.name << ": something connected to port " << listener.port();
  }
  fs::remove(file);
}

INSTANTIATE_TEST_SUITE_P(Battery, HostileRun, ::testing::Combine(::testing::ValuesIn(files_in("run")), ::testing::Bool()),
                         [](const ::testing::TestParamInfo<RunCase>& run) {
                           return std::get<0>(run.param) + (std::get<1>(run.param) ? "_in_a_constructor" : "_in_the_call");
                         });

// What each file of hostile/compile must be refused with, after "FILE:".
std::string expected_refusal(const std::string& name) {
  const std::string allowed =
      " is refused: graded code may include the standard library's headers by name (#include <cmath>) and impulse/workshop.h, nothing else";
  const std::map<std::string, std::string> refusals = {
      {"include_outside", "2: #include \"/etc/passwd\"" + allowed},
      {"include_urandom", "2: #include </dev/urandom>" + allowed},
      {"include_spliced", "2: #include \"/etc/passwd\"" + allowed},
      {"include_digraph", "2: #include \"/etc/passwd\"" + allowed},
      {"include_computed", "3: #include SECRET is refused: name the header itself (#include <cmath>)"},
      {"include_beside", "2: #include \"../run/read_file.cpp\"" + allowed},
      {"line_rename", "3: #line is refused: graded code may not rename its file or renumber its lines"},
      {"asm_incbin", "2: asm is refused: graded code may not contain assembly"},
      {"template_bomb", " the compiler needed more than the 1 GiB of memory, which a build may not"},
  };
  return refusals.at(name);
}

class HostileCompile : public ::testing::TestWithParam<std::string> {};

TEST_P(HostileCompile, IsRefusedAndNothingOfTheFileShown) {
  const std::string name = GetParam();
  const std::string file = (fs::path(IMPULSE_SOURCE_DIR) / "tests/response/hostile/compile" / (name + ".cpp")).string();
  for (const User& user : users()) {
    const Outcome run = impulse_as(user, {"grade", file});
    EXPECT_EQ(run.result.exit_code, 1) << user.name << ": " << run.result.describe();
    EXPECT_NE(run.result.stderr_text.find(file + ":" + expected_refusal(name)), std::string::npos)
        << user.name << ": " << run.result.stderr_text;
    expect_nothing_leaked(run, user.name);
  }
}

INSTANTIATE_TEST_SUITE_P(Battery, HostileCompile, ::testing::ValuesIn(files_in("compile")));

// After a hostile file, the next student's is graded as before: nothing of the first is left in
// the cache, the machine or impulse.
TEST(Hostile, TheNextStudentIsGradedAsBefore) {
  const std::string honest = std::string(IMPULSE_SOURCE_DIR) + "/assets/workshop/listing1_corrected.cpp";
  const fs::path hostile = battery_directory() / "next_student_hostile.cpp";
  write_file(hostile, text_of(fs::path(IMPULSE_SOURCE_DIR) / "tests/response/hostile/run/fork_loop.cpp") +
                          "__attribute__((constructor)) static void Early() { Hostile(); }\n"
                          "static void AddCollisionImpulse(RigidBody&, RigidBody&, const Vector3&, const Vector3&, float) {}\n");
  for (const User& user : users()) {
    EXPECT_EQ(impulse_as(user, {"grade", hostile.string()}).result.exit_code, 2) << user.name;
    const Outcome next = impulse_as(user, {"grade", honest});
    EXPECT_EQ(next.result.exit_code, 0) << user.name << ": " << next.result.describe();
    EXPECT_NE(next.out.find("13 of 13 cases pass"), std::string::npos) << user.name << ": " << next.out;
  }
}

// Its limits are in force before any of its code runs: a constructor reads them, and its user.
TEST(Hostile, LimitsHoldBeforeTheFirstConstructor) {
  for (const User& user : users()) {
    const Outcome run = impulse_as(user, {"response", std::string(IMPULSE_SOURCE_DIR) + "/tests/response/responses/limits.cpp"});
    ASSERT_EQ(run.result.exit_code, 0) << user.name << ": " << run.result.describe();
    for (const char* limit : {"address space 536870912\n", "processor time 120\n", "file size 0\n", "open files 8\n", "processes 0\n", "core 0\n"})
      EXPECT_NE(run.result.stderr_text.find(limit), std::string::npos) << user.name << ": " << limit << " in " << run.result.stderr_text;
  }
}

}  // namespace
}  // namespace impulse::workshop
