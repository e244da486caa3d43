// Builds a submission's Tutorial10.cpp like a stage, by one compiler call in the job's sandbox with the
// recipe the build wrote (host_kit.txt), and keeps the program in the grader's cache under the hash
// of everything that went into it.
#include "compile/build.hpp"

#include "intake/staging.hpp"
#include "t10/error.hpp"

#include <fstream>
#include <sstream>
#include <system_error>

namespace t10::grade {

namespace fs = std::filesystem;

namespace {

std::vector<std::string> splitList(const std::string& text) {
    std::vector<std::string> items;
    std::stringstream in(text);
    for (std::string item; std::getline(in, item, ';');)
        if (!item.empty()) items.push_back(item);
    return items;
}

} // namespace

HostKit loadHostKit() {
    HostKit kit;
    kit.text = readFile(T10_GRADE_HOST_KIT);
    std::stringstream in(kit.text);
    for (std::string line; std::getline(in, line);) {
        const auto space = line.find(' ');
        const std::string key = line.substr(0, space);
        const std::string value = space == std::string::npos ? "" : line.substr(space + 1);
        if (key == "compiler") kit.compiler = value;
        else if (key == "flags") kit.flags = splitList(value);
        else if (key == "includes") kit.includes = splitList(value);
        else if (key == "defines") kit.defines = splitList(value);
        else if (key == "libs") kit.libs = splitList(value);
        else if (key == "pch") kit.pch = value;
    }
    // A kit whose header was not precompiled (a build that stopped before it) builds without it.
    std::error_code error;
    if (!kit.pch.empty() && !fs::is_regular_file(fs::path(kit.pch) / "t10" / "app.hpp.gch", error)) kit.pch.clear();
    if (kit.compiler.empty()) throw Error(std::string(T10_GRADE_HOST_KIT) + ": no compiler line");
    return kit;
}

std::vector<Mount> projectMounts(const HostKit& kit) {
    std::vector<Mount> mounts;
    // The project's public files at neutral paths (/t10/...): host paths do not show inside.
    for (std::size_t i = 0; i < kit.includes.size(); ++i) {
        const std::string inside = "/t10/include/" + std::to_string(i);
        mounts.push_back({kit.includes[i], inside, false});
    }
    if (!kit.pch.empty()) mounts.push_back({kit.pch, kPchInside, false});
    for (std::size_t i = 0; i < kit.libs.size(); ++i) {
        const std::string& lib = kit.libs[i];
        if (lib.empty() || lib[0] != '/' || lib.rfind("/usr/", 0) == 0) continue;
        mounts.push_back({lib, "/t10/lib/" + std::to_string(i) + "-" + fs::path(lib).filename().string(), false});
    }
    // The common shaders and assets keep their host paths: libt10_common.a has them compiled in. They
    // are the one place where the project's location shows inside.
    for (const std::string& define : kit.defines) {
        for (const std::string name : {"T10_COMMON_SHADER_DIR=", "T10_ASSET_DIR="}) {
            if (define.rfind(name, 0) != 0) continue;
            const std::string path = define.substr(name.size() + 1, define.size() - name.size() - 2);
            mounts.push_back({path, path, false});
        }
    }
    return mounts;
}

std::string buildProgram(const HostKit& kit, const std::string& stage, const std::string& cacheDir, const SandboxRun& sandbox,
                         const std::string& source, const fs::path& work, std::string& log) {
    // The key: the code, the recipe, the sandbox's layout, and when each library was last built (a
    // rebuilt common/ must not leave stale programs in the cache). Every part is built the same way:
    // Part 3's blur passes are recorded at run time by the frame loop's capture hook (--capture-passes).
    std::string key = kit.text + stage + readFile(source) + "sandbox layout 2 " + isolationName(sandbox.isolation);
    std::vector<std::string> inputs = kit.libs;
    if (!kit.pch.empty()) inputs.push_back((fs::path(kit.pch) / "t10" / "app.hpp.gch").string());
    for (const std::string& file : inputs) {
        std::error_code error;
        const auto time = fs::last_write_time(file, error);
        if (!error) key += file + std::to_string(time.time_since_epoch().count());
    }
    const fs::path dir = fs::absolute(cacheDir) / "builds" / hashOf(key);
    const std::string program = (dir / "student").string();
    if (fs::exists(dir) && manifestHolds(dir)) {
        log = readFile((dir / "build.log").string());
        return program;
    }
    std::error_code ignored;
    fs::remove_all(dir, ignored); // absent, or failed its hashes: built again

    SandboxRun run = sandbox;
    const fs::path out = work / ("build" + uniqueSuffix());
    makeDir(out, run.uid, 0700);
    run.mounts.push_back({source, "/submission/Tutorial10.cpp", false});
    run.mounts.push_back({out.string(), "/out", true});
    run.workingDirectory = "/out";
    const bool namespaces = run.isolation == Isolation::Namespaces;
    run.env = {"PATH=/usr/bin:/bin", "LC_ALL=C", std::string("TMPDIR=") + (namespaces ? "/tmp" : out.string()),
               std::string("HOME=") + (namespaces ? "/tmp" : out.string())};

    std::vector<std::string> argv{kit.compiler};
    argv.insert(argv.end(), kit.flags.begin(), kit.flags.end());
    // First: GCC takes t10/app.hpp.gch there for the stage's first include when it fits this call,
    // and otherwise goes on to the headers themselves. -Winvalid-pch says so in the build's log.
    if (!kit.pch.empty()) argv.insert(argv.end(), {"-Winvalid-pch", "-I" + run.path(kPchInside)});
    for (std::size_t i = 0; i < kit.includes.size(); ++i) argv.push_back("-I" + run.path("/t10/include/" + std::to_string(i)));
    for (const std::string& define : kit.defines) argv.push_back("-D" + define);
    argv.push_back(std::string("-DT10_STAGE_NAME=\"") + stage + "\"");
    // Where the program finds its shaders without --shader-dir: the submission's own folder inside
    // the sandbox (it does not exist outside it).
    argv.push_back("-DT10_STAGE_SHADER_DIR=\"/submission\"");
    // The submission's own file, so that the compiler's messages name it.
    argv.insert(argv.end(), {run.path("/submission/Tutorial10.cpp"), "-o", run.path("/out/student")});
    for (std::size_t i = 0; i < kit.libs.size(); ++i) {
        const std::string& lib = kit.libs[i];
        const bool project = !lib.empty() && lib[0] == '/' && lib.rfind("/usr/", 0) != 0;
        argv.push_back(project ? run.path("/t10/lib/" + std::to_string(i) + "-" + fs::path(lib).filename().string()) : lib);
    }
    const RunResult result = runSandboxed(run, argv, (work / "build.log").string());
    log = result.output;
    const fs::path built = out / "student";
    std::error_code error;
    const bool regular = fs::is_regular_file(fs::symlink_status(built, error));
    if (!result.ok() || !regular) {
        if (!result.timedOut && result.signal == 0 && log.empty()) log = "the compiler " + result.describe();
        if (result.timedOut) log += "\nthe build " + result.describe();
        fs::remove_all(out, ignored);
        return "";
    }
    // Published by the grader: the program, its log, the command, and their hashes.
    const fs::path temporary = dir.string() + uniqueSuffix();
    fs::create_directories(temporary);
    copyFile(built, temporary / "student", 0700);
    std::ofstream(temporary / "build.log") << log;
    {
        // The command, so that an instructor can see how it was built (paths as inside the sandbox).
        std::ofstream script(temporary / "build.sh");
        script << "#!/bin/sh\n# run by t10-grade inside its sandbox (" << isolationName(sandbox.isolation) << ")\n";
        for (const std::string& a : argv) script << "'" << a << "' ";
        script << "\n";
    }
    fs::remove_all(out, ignored);
    writeManifest(temporary);
    publishDirectory(temporary, dir);
    if (!manifestHolds(dir)) return buildProgram(kit, stage, cacheDir, sandbox, source, work, log);
    return program;
}

} // namespace t10::grade
