// A system call that graded code may not make, in words a student understands: "open a file
// ('/etc/passwd')", "start a process (fork, system() or a thread)", "open a network socket".
#pragma once
#include <cstdint>
#include <functional>
#include <string>

namespace impulse::workshop {

// What the call `number` (this machine's numbering) with `arguments` tried to do, for "... tried
// to WORDS, which graded code may not do". `read_text` reads a C string at an address of the
// caller's memory ("" when it cannot).
std::string attempt_words(int number, const uint64_t (&arguments)[6], const std::function<std::string(uint64_t)>& read_text);

// A path as a report quotes it: at most 200 characters, anything unprintable escaped.
std::string quoted_path(const std::string& path);

}  // namespace impulse::workshop
