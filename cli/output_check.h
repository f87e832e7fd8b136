// output_check.h - the one check every command makes before it writes a file: the output is
// none of the files the command reads (docs/security.md, "Output files").
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "shpack/scene/scene.h"

namespace shpack::cli {

// "" when `output` is no file of `inputs`, else "<output>: is both an input and the output".
// Files are compared by identity (device and inode, links followed), so another spelling, a
// symbolic link or a hard link to an input is caught too. An output that does not exist yet,
// "-" and outputs that are not regular files (written in place, atomic_write.h) pass.
std::string check_output_not_input(const std::string& output, const std::vector<std::filesystem::path>& inputs);

// Every file `shpack bake` reads for `scene` (loaded by scene::load_scene): the scene file,
// its environment map, its mesh files and the external buffers of its .gltf meshes.
std::vector<std::filesystem::path> scene_input_files(const scene::Scene& scene);

}  // namespace shpack::cli
