// The scan of a student's text before it is compiled (demos/response/include_check.h): what a
// student writes passes, and every way of naming another file to the compiler is refused with
// the file's line.
#include "demos/response/include_check.h"

#include <gtest/gtest.h>

namespace impulse::workshop {
namespace {

std::string refusal(const std::string& text) { return refused_in_source("mine.cpp", text).value_or(""); }

TEST(IncludeCheck, WhatStudentsWritePasses) {
  EXPECT_EQ(refusal("#include <cmath>\n#include <vector>  // for the contacts\n  #  include <bits/stdc++.h>\n"
                    "#include \"impulse/workshop.h\"\n#include <sys/socket.h>\n#define SQUARE(x) ((x) * (x))\n#pragma once\n"),
            "");
  // Directives' words in comments, strings, raw strings and character literals are not directives.
  EXPECT_EQ(refusal("// #include \"/etc/passwd\"\n/* #line 1 \"x\"\n asm */\nconst char* a = \"#include <x>\";\n"
                    "const char* b = R\"x(\n#include \"/etc/passwd\"\n)x\";\nchar c = '#';\nint n = 1'000'000;\n"),
            "");
}

TEST(IncludeCheck, AnotherFileIsRefusedWithItsLine) {
  const std::string allowed = "graded code may include the standard library's headers by name (#include <cmath>) and impulse/workshop.h";
  EXPECT_EQ(refusal("\n#include \"/etc/passwd\"\n"), "mine.cpp:2: #include \"/etc/passwd\" is refused: " + allowed + ", nothing else");
  EXPECT_NE(refusal("#include </dev/urandom>\n").find("mine.cpp:1: #include </dev/urandom> is refused"), std::string::npos);
  EXPECT_NE(refusal("#include <../../etc/passwd>\n").find("is refused"), std::string::npos);
  EXPECT_NE(refusal("#include \"theirs.cpp\"\n").find("mine.cpp:1: #include \"theirs.cpp\" is refused"), std::string::npos);
  EXPECT_NE(refusal("#include \"cmath\"\n").find("is refused"), std::string::npos);
  EXPECT_NE(refusal("int a;\n#inc\\\nlude \"/etc/passwd\"\n").find("mine.cpp:2: #include \"/etc/passwd\" is refused"), std::string::npos);
  EXPECT_NE(refusal("/* before */ %:include \"/etc/passwd\"\n").find("mine.cpp:1: #include"), std::string::npos);
  EXPECT_NE(refusal("#define F \"/etc/passwd\"\n#include F\n").find("mine.cpp:2: #include F is refused: name the header itself"),
            std::string::npos);
  for (const char* directive : {"include_next <x>", "import \"/etc/passwd\"", "embed \"/etc/passwd\""})
    EXPECT_NE(refusal(std::string("#") + directive + "\n").find("is refused: " + allowed), std::string::npos) << directive;
}

TEST(IncludeCheck, AStandardHeaderWrittenOddlyIsRefusedAsWritten) {
  // The wrapper moves #include lines before the student's namespace; it moves one line, written plainly.
  EXPECT_NE(refusal("#include <cmath> /* x */\n").find("mine.cpp:1: #include <cmath> is refused as written"), std::string::npos);
  EXPECT_NE(refusal("#inc\\\nlude <cmath>\n").find("is refused as written"), std::string::npos);
}

TEST(IncludeCheck, LinesFileNamesAssemblyAndProbesAreRefused) {
  EXPECT_NE(refusal("int a;\n#line 1 \"/etc/passwd\"\n").find("mine.cpp:2: #line is refused"), std::string::npos);
  EXPECT_NE(refusal("# 1 \"/etc/passwd\"\n").find("mine.cpp:1: a line marker"), std::string::npos);
  EXPECT_NE(refusal("asm(\".incbin \\\"/etc/passwd\\\"\");\n").find("mine.cpp:1: asm is refused"), std::string::npos);
  EXPECT_NE(refusal("void f() { __asm__ volatile(\"\"); }\n").find("__asm__ is refused"), std::string::npos);
  EXPECT_NE(refusal("#if __has_include(\"/etc/shadow\")\n#endif\n").find("mine.cpp:1: __has_include is refused"), std::string::npos);
  EXPECT_NE(refusal("_Pragma(\"GCC dependency \\\"/etc/passwd\\\"\")\n").find("_Pragma is refused"), std::string::npos);
  EXPECT_NE(refusal("#pragma GCC dependency \"/etc/passwd\"\n").find("#pragma GCC dependency is refused"), std::string::npos);
}

}  // namespace
}  // namespace impulse::workshop
