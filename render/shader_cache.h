// Where llvmpipe keeps the shaders it compiles between runs.
//
// Mesa 22.3's llvmpipe keys its on-disk shader cache by the CPU's features but not by its vector
// width (LP_NATIVE_VECTOR_WIDTH). A vertex shader compiled 8 vertices wide (256 bits, the default
// on AVX machines) and loaded by a process running 4 wide (128 bits) writes 8 vertices at a time
// into a buffer llvmpipe sized for multiples of 4: a heap overflow on any draw of a vertex count
// that is not a multiple of 8 (render/README.md, "Mesa's shader cache and the vector width"). So each width gets a
// cache directory of its own.
#pragma once

namespace impulse::render {

// Sets MESA_SHADER_CACHE_DIR to a directory named after the vector width in force, inside the
// directory Mesa would use (MESA_SHADER_CACHE_DIR, $XDG_CACHE_HOME/mesa_shader_cache or
// $HOME/.cache/mesa_shader_cache), or disables the cache when there is none. Takes effect for
// contexts created afterwards; GlContext calls it before its first. Runs once per process.
void separate_shader_cache_by_vector_width();

}  // namespace impulse::render
