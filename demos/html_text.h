// Text for an HTML page (the gallery, verify's report): &, <, > and " written as entities, so a
// scene's title or a file name never breaks the page.
#pragma once
#include <string>

namespace impulse::demos {

std::string html(const std::string& text);

}  // namespace impulse::demos
