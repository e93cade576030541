// What a student's file may not ask of the compiler, found in its text before the compiler runs:
// an #include of anything but a standard header by name or impulse's own header (another file
// would be read, and its lines shown in the compiler's messages), #include_next, #import and
// #embed, #line (which names the file a message quotes), #pragma GCC dependency, __has_include,
// _Pragma, and asm (whose .incbin would pull a file into the shared object). The text is read as
// the preprocessor reads it: lines joined at a backslash, comments, string and raw-string
// literals skipped, digraphs (%:) seen. The Landlock ruleset the compiler runs under
// (compile_sandbox.h) refuses what gets past this, where the kernel has Landlock.
#pragma once
#include <optional>
#include <string>

namespace impulse::workshop {

// The first thing refused, as "FILE:LINE: what, and why", or nothing. `label` names the file.
std::optional<std::string> refused_in_source(const std::string& label, const std::string& text);

// Whether a line is an #include that the wrapper moves before the student's namespace: a
// standard header (<...>) or impulse's, alone on its line but for a // comment.
bool is_hoisted_include(const std::string& line);

}  // namespace impulse::workshop
