// The effects part of a scene file (samples/common/scene.h documents the keys).
#pragma once

#include "scene.h"

#include <nlohmann/json.hpp>

#include <string>

namespace pfs {

/// Reads "preset", "features", "force_fields", "obstacles", "emitters" and "sinks" of the scene
/// root into s (params are applied by the caller, which orders preset before "params").
/// Throws pfs::Error("<path>: <JSON Pointer>: <reason>").
void parse_scene_effects(const nlohmann::json& root, const std::string& path, Scene& s);

/// "obstacles,emitters" -> PF_FEATURE_* bits ("all", "none" and "" allowed); throws Error
/// naming `what` for an unknown name.
uint32_t parse_feature_list(const std::string& list, const char* what);

} // namespace pfs
