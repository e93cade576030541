// A TOML syntax error in plain words. toml++ says what its parser expected ("Error while parsing
// string: unescaped control characters other than TAB (U+0009) are explicitly prohibited"); a
// lecturer needs what is wrong in the file and what to write instead ("a string opened on line 12
// is not closed: end it with the quote it opens with ..."). The common mistakes (a string, a
// table header, an inline table or an array left open; a key without '=' or without a value; a key
// or table given twice; a bare word; two things on a line) are said so; any other keeps toml++'s
// words.
#pragma once
#include <string>
#include <string_view>

namespace impulse::demos {

// What to say about a parse error toml++ describes as `description` at `line` and `column` (from
// 1) of the file whose text is `text`; without the "FILE:LINE: " the caller puts before it.
std::string plain_syntax_error(std::string_view description, int line, int column, std::string_view text);

}  // namespace impulse::demos
