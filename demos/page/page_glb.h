// A scene's run as a glTF 2.0 binary (`impulse export --format glb`), for Blender (File > Import >
// glTF 2.0), three.js and any other glTF viewer: the scene run once as the film runs it
// (WorldTake), each body a node with its mesh and colour, and one animation of their poses at the
// video's frames.
#pragma once
#include "demos/scene/scene.h"

#include <ostream>

namespace impulse::demos {

// The .glb: one node per body, named as the body, with a mesh in the body's frame (a plane's in the
// world's: a square in it, centred on its point nearest the camera's target) and a PBR material of the body's
// colour (converted to linear, as glTF's colour factors are; the ground in the video's light grey);
// each rod or rope (a distance joint) a grey rod from anchor to anchor, under a node "joints"; a
// camera node as the scene's camera; and one animation "run" with, for each body and rod whose
// pose changes during the run, its translation and rotation (a rod's scale: its length) at every
// video frame (k / fps s), linear.
// With `marks`, also the video's arrows (contact normals, impulses, friction, velocities: each
// frame's scene_draw_list at the scene's camera, with the run's arrow scales, as the page's marks)
// under a node "marks": a node per kind ("impulse", "impulse faint", ...: one per colour), holding a
// node per slot ("impulse 1", ...: as many as that colour's most arrows in one frame; a frame's
// arrows fill its first slots in the draw list's order). A slot's mesh is a unit arrow along +y (a
// shaft, then a cone over its last quarter), unlit (KHR_materials_unlit) in the arrow's colour; the
// animation "run" sets, per video frame, stepped, its translation (the arrow's origin), rotation
// (+y onto the arrow) and scale (s, length, s), s = min(1, length / 0.4 m) thinning short arrows;
// scale 0 where the slot has no arrow. Without `marks`, none of this is written.
// Metres, y up, as the engine's world. Throws std::runtime_error if it cannot write.
void write_glb(const Scene& scene, std::ostream& out, bool marks = false);

}  // namespace impulse::demos
