// PNG files <-> Frames through libpng. Errors throw std::runtime_error naming the file.
#pragma once
#include <string>

#include "render/frame.h"

namespace impulse::render {

// 8-bit RGBA. Writes its own temporary and renames it (part_file.h), so `path` is either complete
// or untouched.
void write_png(const std::string& path, const Frame& frame);

// Any PNG (grey, palette, 16-bit, interlaced, with or without alpha) as 8-bit RGBA.
Frame read_png(const std::string& path);

}  // namespace impulse::render
