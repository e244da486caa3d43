// The scene's options group on the command line: what is drawn (--scene, --camera, --input,
// --keep-non-finite) and where shaders are looked for first (--shader-dir).
#pragma once
#include <string>

namespace CLI {
class App;
}

namespace t10 {

struct SceneSettings {
    std::string scene;          // --scene FILE.gltf|.glb (empty: the built-in scene)
    std::string camera;         // --camera NAME (empty: the scene's first camera)
    std::string input;          // --input FILE.exr, replaces the scene by an HDR image
    bool keepNonFinite = false; // --keep-non-finite: NaN and infinity of --input reach the stage as they are
    std::string shaderDir;      // --shader-dir DIR, searched before the stage's own folder
};

// Adds the "Scene" group to `cli`; bad values end the parse with t10::UsageError.
void addSceneOptions(CLI::App& cli, SceneSettings& settings);

} // namespace t10
