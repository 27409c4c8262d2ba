// Reading the parts of a scene file that belong to Paper B's model (the
// "cdem" section, a block's "mesh") and validating the whole CDEM scene by
// building its model. Internal to dda_io (scene_read.cpp calls these).
#pragma once
#include <string>

#include "dda/io/scene_file.hpp"
#include "json_reader.hpp"

namespace dda::io::detail {

ContactModel read_model(const Reader& r, const json* v);
// The "cdem" section (v may be null: every option at its default).
CdemSettings read_cdem(const Reader& r, const json* v);
// A block's "mesh" (`block` has its vertices already).
CdemMesh read_block_mesh(const Reader& r, const json& v, const std::string& path, const BlockSpec& block);
// Builds the CDEM model of the file (meshes, critical step, options): its
// SceneError comes back as SceneFileError with the file's field names.
void check_cdem(const Reader& r, const SceneFile& file);

}  // namespace dda::io::detail
