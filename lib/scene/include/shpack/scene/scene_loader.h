// scene_loader.h - reading a scene file for `shpack bake` (docs/scenes.md).
//
// The file is parsed with nlohmann-json and validated against docs/scene.schema.json (built
// into the library, validated with valijson), then checked for what a schema cannot say:
// finite numbers, non-zero directions, a rect's orthogonal axes, a spot's inner angle not
// beyond its outer one, effects that need another (shadows needs direct, sky_occlusion needs
// environment), and files that exist (the environment map; meshes, which are read here).
//
// Every error is one line naming the scene file and the JSON path of the offending value,
// "scene.json: lights[2].radius: must be > 0"; a referenced file's problem names that file as
// well, "scene.json: geometry[0].path: chair.obj: no such file". On failure `out` is left
// untouched. `path` "-" reads the scene from stdin (named "stdin"), the files it names then
// relative to the current folder.
#pragma once

#include <filesystem>

#include "shpack/io/io_status.h"
#include "shpack/scene/scene.h"

namespace shpack::scene {

io::IoStatus load_scene(const std::filesystem::path& path, Scene& out);

// The built-in JSON Schema (the text of docs/scene.schema.json).
const char* scene_schema_text() noexcept;

}  // namespace shpack::scene
