// The glTF 2.0 schema's types and ranges for every property the scene loader (gltf_scene.cpp) reads,
// checked on the raw JSON before tinygltf parses it. Why: tinygltf 2.7 replaces a wrongly typed
// value by its default without a word (a string `scale`, a `primitives` object), so the file would
// be drawn differently from what it says. Properties the loader does not read are not checked.
#pragma once
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>

namespace t10 {

// The first fault as "<JSON path>: <fault>", e.g. "meshes[0].primitives: expected an array, got an
// object", or nothing when every property read is well typed and in range. `bytes` is a .gltf file
// or a GLB (its JSON chunk is checked). JSON that does not parse, and a GLB whose header is broken,
// give nothing too: tinygltf reports those with its own messages (line and column).
std::optional<std::string> gltfSchemaFault(const std::uint8_t* bytes, std::size_t size);

} // namespace t10
