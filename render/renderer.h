// Draws a DrawList into an RGBA Frame with OpenGL 4.5 core on an offscreen OSMesa context:
// shadowed, lit spheres, boxes, cylinders, flat meshes, arrows and points over a gridded ground
// plane, anti-aliased.
// Each Renderer owns its own GL context; use it from one thread at a time.
#pragma once
#include <memory>

#include "render/draw_list.h"
#include "render/frame.h"
#include "render/read_back.h"

namespace impulse::render {

// How spheres become pixels. Both give outlines within a quarter pixel of a true circle at any
// size; tests/bench/render_bench measures both (tests/bench/README.md).
enum class SphereMethod {
  impostor,     // a quad per sphere, ray-cast per multisample in the fragment shader
  tessellated,  // an icosphere per sphere, subdivided by its size on screen
};

// Where shadows fall. Both come from the one directional light.
enum class ShadowMethod {
  ground,      // on the ground only, drawn as geometry: cheap, and what makes heights read
  shadow_map,  // on everything, from a depth map the light sees (costs a pass and a lookup a pixel)
  none,
};

// How edges are smoothed. tests/bench/render_bench measures each one's speed and its error against
// a 16x supersampled image (antialias_reference.h); tests/render/antialias_test holds edges to
// no worse than 4x MSAA.
enum class Antialiasing {
  edges,  // one sample a pixel; each pixel an outline crosses mixed by its coverage (edge_antialias.h)
  msaa,   // `samples` samples a pixel, resolved (4x: twice the drawing time of the others on llvmpipe)
  none,
};

struct RendererSettings {
  Antialiasing antialiasing = Antialiasing::edges;
  int samples = 4;              // multisamples a pixel with Antialiasing::msaa
  ShadowMethod shadows = ShadowMethod::ground;
  int shadow_map_size = 2048;   // texels a side, for ShadowMethod::shadow_map
  SphereMethod spheres = SphereMethod::impostor;
  // No sky, no ground, no ground shadows: alpha 0 where nothing is drawn, for laying the frames
  // over a slide. The frame is then premultiplied (colour times alpha) until unpremultiply().
  bool transparent = false;
};

class Renderer {
 public:
  // Throws std::runtime_error if the GL context or its framebuffers cannot be made.
  Renderer(int width, int height, RendererSettings settings = {});
  ~Renderer();
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  // The returned frame is owned by the renderer and overwritten by the next draw().
  // Throws std::invalid_argument if the camera's position equals its target.
  const Frame& draw(const DrawList& draw_list);
  // The same, into a frame of the caller's (resized as needed): lets a pipeline keep several.
  void draw_into(const DrawList& draw_list, Frame& frame);
  // Draws and reads the image back without its last step on the CPU: render::finish(read_back,
  // frame), on any thread, then gives what draw_into gives. Lets a pipeline draw the next frame
  // meanwhile.
  void draw_into(const DrawList& draw_list, ReadBack& read_back);

  // Moves the image by a fraction of a pixel (x right, y down) in every later draw: the
  // supersampled reference draws the frame at 16 such offsets (antialias_reference.h).
  void set_subpixel_offset(float x, float y);

  int width() const;
  int height() const;
  const RendererSettings& settings() const;

 private:
  struct Gpu;  // every GL object, behind one pointer so this header stays free of GL
  std::unique_ptr<Gpu> gpu_;
  ReadBack read_back_;
  Frame frame_;
};

}  // namespace impulse::render
