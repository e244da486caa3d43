// The scene's command-line options; see scene_options.hpp.
#include "t10/scene_options.hpp"

#include "t10/args.hpp"
#include "t10/error.hpp"

#include <CLI/CLI.hpp>

namespace t10 {

void addSceneOptions(CLI::App& cli, SceneSettings& settings) {
    CLI::Option_group* group = cli.add_option_group("Scene", "What is drawn");
    group->add_option("--camera", settings.camera, "A camera of the scene (built-in: default, floor, lights, crates; "
                                                   "any scene: framing; default: the scene's first)");
    group->add_option("--scene", settings.scene,
                      "Render this glTF 2.0 file (.gltf or .glb) instead of the built-in scene");
    group->add_option("--shader-dir", settings.shaderDir, "Look for shaders in DIR before the stage's own folder")
        ->check(CLI::ExistingDirectory);
    group->add_option("--input", settings.input, "Post-process this HDR image (OpenEXR) instead of rendering the scene")
        ->check(CLI::ExistingFile);
    group->add_flag("--keep-non-finite", settings.keepNonFinite,
                    "Pass NaN and infinite pixels of --input on unchanged (default: +infinity becomes the largest half "
                    "float, 65504, NaN and -infinity 0, with a warning; for testing a stage's own handling)");
    group->callback([&settings] {
        if (!settings.scene.empty() && !hasSuffix(settings.scene, ".gltf") && !hasSuffix(settings.scene, ".glb")) {
            throw UsageError("--scene " + settings.scene + ": the file name must end in .gltf or .glb");
        }
    });
}

} // namespace t10
