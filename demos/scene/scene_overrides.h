// --set KEY=VALUE: any scene field from the command line. Each is written into the scene file's
// TOML before it is read, so a value goes through exactly the checks a field of the file gets,
// and every message about it names the --set argument instead of a line of the file.
//
//   world.friction=false   world.method=projection   body[ball].restitution=0.2   body[0].mass=2
//   video.quality=low      caption[1].text=Hello     camera.position=[0, 2, 8]
//
// KEY is a path of table names; [[body]], [[joint]] and the other lists of tables take an index
// from 0 or, where the tables have names, a name in brackets. VALUE is one value written as in a
// scene file (false, 0.2, [0, 1, 0], "projection"); a bare word is taken as a string. Anything
// after the value (a line break and a second assignment, words after a number) is refused.
#pragma once
#include <toml++/toml.h>

#include <map>
#include <string>
#include <vector>

namespace impulse::demos {

// The nodes the --set arguments wrote, each with its argument ("--set body[0].mass=2"), which the
// scene's messages name instead of a line.
using WrittenNodes = std::map<const toml::node*, std::string>;

// Writes each argument into `root`; returns the nodes written. Throws SceneError naming the
// argument for a malformed one or a path that names nothing.
WrittenNodes apply_overrides(toml::table& root, const std::vector<std::string>& settings);

// "did you mean 'x'?" for the closest of `known` to `word` (a typo or two away), else "".
std::string did_you_mean(const std::string& word, const std::vector<std::string>& known);

}  // namespace impulse::demos
