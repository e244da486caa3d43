// The cases every submission renders, the synthetic inputs two of them read, and the reference
// stage's renders of them (kept in the grader's cache), against which the checks compare.
#include "capture/cases.hpp"

#include "intake/staging.hpp"
#include "isolation/run_limited.hpp"
#include "t10/contract.hpp"
#include "t10/error.hpp"

#include <iostream>

namespace t10::grade {

namespace fs = std::filesystem;

std::string prepareInputs(const std::string& cacheDir, const fs::path& publicInputs) {
    const std::string inputsDir = (fs::absolute(cacheDir) / "inputs").string();
    // Inputs of an older grader (without ramp.exr) or whose recorded hashes no longer hold are made again.
    if (fs::exists(inputsDir) && (!manifestHolds(inputsDir) || !fs::exists(inputsDir + "/ramp.exr")))
        fs::remove_all(inputsDir);
    if (!fs::exists(inputsDir)) {
        const std::string temporary = inputsDir + uniqueSuffix();
        fs::create_directories(temporary);
        const RunResult result = runLimited({std::string(T10_GRADE_BIN_DIR) + "/make_test_images", temporary},
                                            Limits{}, temporary + ".log");
        if (!result.ok()) throw Error("make_test_images " + result.describe() + ":\n" + result.output);
        fs::remove(temporary + ".log");
        writeManifest(temporary);
        publishDirectory(temporary, inputsDir);
    }
    // The jobs read a copy: the cache itself is the grader's alone.
    fs::copy(inputsDir, publicInputs);
    fs::remove(publicInputs / kManifest);
    fs::permissions(publicInputs, fs::perms::owner_all | fs::perms::group_read | fs::perms::group_exec |
                                       fs::perms::others_read | fs::perms::others_exec, fs::perm_options::replace);
    return inputsDir;
}

std::string renderReference(const std::string& referenceBinary, const std::string& stage,
                            const std::vector<std::string>& shaders, const std::string& stageDir, const std::string& cacheDir,
                            const std::string& inputsDir, int part) {
    // The reference renders are kept until the reference program or its shaders change, and used only
    // while their recorded hashes hold; the reference is trusted code and renders outside the sandbox.
    std::string stamp = referenceBinary + " with a Mesa cache seed";
    for (const std::string& setting : kLlvmpipeSmallRenders) stamp += ", " + setting;
    stamp += std::to_string(fs::last_write_time(referenceBinary).time_since_epoch().count());
    for (const std::string& shader : shaders) stamp += readFile(stageDir + "/" + shader);
    const std::string referenceDir = (fs::absolute(cacheDir) / ("reference-" + stage + "-" + hashOf(stamp))).string();
    if (fs::exists(referenceDir) && manifestHolds(referenceDir)) return referenceDir;
    if (fs::exists(referenceDir)) {
        std::cerr << "t10-grade: warning: " << referenceDir << " does not match its recorded hashes: rendered again\n";
        fs::remove_all(referenceDir);
    }
    const std::string temporary = referenceDir + uniqueSuffix();
    // Every case in one process (the stage's --then), as the submissions' are rendered.
    std::vector<std::string> argv{referenceBinary};
    for (const CaseSpec& spec : cases(part)) {
        const std::string out = temporary + "/" + spec.id;
        fs::create_directories(out);
        if (argv.size() > 1) argv.push_back(contract::kThenOption);
        argv.insert(argv.end(), {"--headless", "--backend", "egl", "--frames", "1"});
        for (const std::string& a : caseArgs(spec.args, inputsDir)) argv.push_back(a);
        argv.insert(argv.end(), {"--dump", out, "--output", out + "/frame.png"});
    }
    // Its compiled shaders seed each submission's own Mesa cache: most of a submission's shaders
    // are the reference's, and compiling them again costs more than the render.
    std::vector<std::string> environment = kLlvmpipeSmallRenders;
    environment.push_back("MESA_SHADER_CACHE_DIR=" + temporary + "/mesa-seed");
    const RunResult result = runLimited(argv, Limits{}, temporary + "/run.log", "", environment);
    if (!result.ok()) throw Error("the reference " + stage + " " + result.describe() + ":\n" + result.output);
    writeManifest(temporary);
    publishDirectory(temporary, referenceDir);
    if (!manifestHolds(referenceDir)) throw Error(referenceDir + ": changed while it was published");
    return referenceDir;
}

} // namespace t10::grade
