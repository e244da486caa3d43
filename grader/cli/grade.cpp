// t10-grade: grades students' versions of a Tutorial 10 stage.
//   t10-grade --part 1|2|3 [--report DIR] [--jobs N] [--timeout S] [--cache DIR] [--format F]...
//             [--name-from N|PATTERN] [--roster CSV] [--fill-from-reference P] [--isolation I] SUBMISSION...
// A submission is a folder with any of Tutorial10.cpp and the part's shaders. It is copied first, as
// hostile input, into a private folder (submission_files.hpp), where the reference files the
// instructor lets come from the reference are added. Every step the student controls (the compiler,
// each render) runs in a sandbox (sandbox.hpp); its outputs are read afterwards as hostile files
// (capture.hpp). Its host code is built against common/ in a build folder of its own (build.hpp),
// then it renders four cases under limits (a power-of-two size with one camera, a
// non-power-of-two size with another, and two synthetic inputs: black pixels next to pixels far
// above the white point, and one hot pixel), and checks.hpp compares every buffer with the CPU
// reference and the frame with the reference stage (FLIP). Part 3 programs run with --capture-passes
// (the frame loop's capture hook, frame_observer.hpp), which records each blur pass beside the dump. Writes DIR/<submission>/report.json and
// report.html (and the platforms' results of --format, formats.hpp), DIR/gradebook.csv, and the class
// index DIR/index.html with DIR/grades-lms.csv (class_index.hpp). Exit 0 when every submission got a
// report, 1 when the grader failed, 2 on bad usage.
#include "compile/build.hpp"
#include "cli/command_line.hpp"
#include "capture/capture.hpp"
#include "capture/cases.hpp"
#include "checks/checks.hpp"
#include "checks/dump_files.hpp"
#include "checks/flip.hpp"
#include "part/part.hpp"
#include "report/check_images.hpp"
#include "report/class_index.hpp"
#include "platforms/formats.hpp"
#include "report/output.hpp"
#include "report/report.hpp"
#include "similarity/similarity.hpp"
#include "isolation/run_limited.hpp"
#include "isolation/sandbox.hpp"
#include "intake/staging.hpp"
#include "intake/submission_files.hpp"

#include "t10/error.hpp"
#include "t10/error_line.hpp"
#include "t10/image_io.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <future>
#include <iostream>
#include <map>
#include <mutex>
#include <set>
#include <sstream>
#include <cstring>
#include <sys/stat.h>
#include <thread>
#include <unistd.h>

namespace fs = std::filesystem;

namespace {

using t10::Error;
using t10::errorLine;
using t10::UsageError;
using namespace t10::grade;

// The files of a part, and those its steps ask the student to change.
PartFiles partFiles(const Part& part) {
    PartFiles files{{"Tutorial10.cpp"}, part.asked};
    for (const std::string& shader : part.shaders) files.expected.push_back(shader);
    return files;
}

// Tools name the submission's files by their paths in the sandbox (or the grader's private copy):
// the report names them after the submission folder instead, as the student knows them.
std::string studentPaths(std::string text, const fs::path& work, const std::string& submission) {
    for (const std::string& prefix : {std::string("/submission/"), "/" + std::string(kNanProbeFolder) + "/",
                                      (work / "submission").string() + "/", (work / kNanProbeFolder).string() + "/"}) {
        for (auto at = text.find(prefix); at != std::string::npos; at = text.find(prefix, at)) {
            text.replace(at, prefix.size(), submission + "/");
            at += submission.size() + 1;
        }
    }
    return text;
}

// Where one submission is graded: its parallel job, its report folder, its private work folder
// (the copy of the submission is work/submission) and the sandbox its renders start from.
struct Job {
    int index;
    fs::path out;
    fs::path work;
    SandboxRun base;
    fs::path shaders() const { return work / "submission"; }
};

class Grader {
public:
    explicit Grader(Config config);
    ~Grader() {
        std::error_code error;
        if (!workRoot_.empty()) fs::remove_all(workRoot_, error);
    }
    Grader(const Grader&) = delete;
    Grader& operator=(const Grader&) = delete;

    Report grade(const std::string& submission, const std::string& name, int job) const;
    Isolation isolation() const { return isolation_; }
    // --jobs, or 1 where the jobs could not each have their own process limit (chooseIsolation says so).
    int jobs() const { return config_.jobs; }

private:
    void chooseIsolation();
    std::string referenceStageDir() const { return std::string(T10_GRADE_SOURCE_DIR) + "/" + info_.stage; }
    SandboxRun sandbox(int job, const SandboxLimits& limits) const;
    // Builds Tutorial10.cpp (a host path) in the sandbox of `job`; returns the cached program (a host
    // path only the grader can read), or "" with the compiler's message in `log`.
    std::string build(const std::string& source, int job, const fs::path& work, std::string& log) const;
    // The steps of grade(). Those that return bool (or "") set the report's status and message when
    // the submission stops there.
    Report startReport(const std::string& submission, const std::string& name) const;
    fs::path makeJobFolder(uid_t uid) const;
    bool copyIn(const std::string& submission, const Job& job, Report& report) const;
    std::string buildSubmission(const Job& job, Report& report) const;
    fs::path stageProgram(const std::string& built, const Job& job) const;
    // Renders `specs` in one process in the sandbox, each into caseDir() (made here, for the job's uid).
    RunResult renderCases(const std::vector<CaseSpec>& specs, const Job& job, const fs::path& program) const;
    static fs::path caseDir(const Job& job, const CaseSpec& spec) { return job.work / ("out-" + spec.id); }
    void reportFailedRun(const CaseSpec& spec, const RunResult& result, const Job& job, Report& report) const;
    bool captureCases(const Job& job, const fs::path& program, Report& report, std::vector<CaseRun>& runs) const;
    std::vector<Check> checkCase(const CaseSpec& spec, const CaseRun& run, const Job& job) const;
    void score(const std::vector<CaseRun>& runs, const Job& job, Report& report) const;

    Config config_;
    const Part& info_;
    PartFiles files_;
    HostKit kit_;
    std::string referenceBinary_;
    std::string inputsDir_;
    std::string referenceDir_;
    Isolation isolation_ = Isolation::None;
    std::vector<uid_t> jobUids_;     // one per parallel job when root, else none
    bool ownProcessLimit_ = false;   // not root: each sandbox's process limit counts its own job only
    fs::path workRoot_;              // private copies, programs and outputs of the jobs
    fs::path publicInputs_;          // the synthetic inputs, readable by the jobs
    std::vector<Mount> projectMounts_; // headers, libraries, common shaders and assets, read-only
};

Grader::Grader(Config config) : config_(std::move(config)), info_(partInfo(config_.part)), files_(partFiles(info_)),
                                kit_(loadHostKit()) {
    if (!fs::exists(T10_GRADE_FLIP)) {
        throw Error(std::string(T10_GRADE_FLIP) + ": FLIP (the perceptual image metric) is not installed; run "
                    "`make grade-deps` (a pinned flip-evaluator in a venv under build/)");
    }
    referenceBinary_ = std::string(T10_GRADE_BIN_DIR) + "/" + info_.stage;
    if (!fs::exists(referenceBinary_)) throw Error(referenceBinary_ + ": the reference stage is not built");
    fs::create_directories(config_.cacheDir);
    fs::create_directories(config_.reportDir);
    // The cache belongs to the grader: no job uid may read or write it.
    fs::permissions(config_.cacheDir, fs::perms::owner_all, fs::perm_options::replace);
    chooseIsolation();
    workRoot_ = fs::temp_directory_path() / ("t10-grade" + uniqueSuffix());
    makeDir(workRoot_, 0, 0711); // the jobs may pass through it, not list it

    projectMounts_ = projectMounts(kit_);

    // As root the jobs run as uids of their own: a checkout they cannot enter (inside a 0700 home) is
    // staged where they can, or the run stops saying which folder and what to do.
    if (!jobUids_.empty()) stageUnreachableMounts(projectMounts_, (workRoot_ / "project").string(), jobUids_.front(), isolation_);
    publicInputs_ = workRoot_ / "inputs";
    inputsDir_ = prepareInputs(config_.cacheDir, publicInputs_);
    // The reference host code (for submissions without Tutorial10.cpp) is built once here rather than
    // by each of the parallel jobs, while the reference renders its cases: the two are independent and
    // each keeps one core busy (on a fresh cache they are most of a part's start).
    const fs::path work = workRoot_ / "reference-host";
    makeDir(work, 0, 0755);
    // Built from a copy in the work folder, like a submission: the job's uid may not reach the checkout.
    copyFile(referenceStageDir() + "/Tutorial10.cpp", work / "Tutorial10.cpp", 0644);
    std::string log;
    // The future waits for the build in its destructor, also when the reference throws.
    std::future<std::string> host = std::async(std::launch::async, [&] { return build((work / "Tutorial10.cpp").string(), 0, work, log); });
    referenceDir_ = renderReference(referenceBinary_, info_.stage, info_.shaders, referenceStageDir(), config_.cacheDir,
                                    inputsDir_, config_.part);
    if (host.get().empty()) {
        throw Error("the reference " + std::string(info_.stage) + "/Tutorial10.cpp does not build in the sandbox:\n" + log);
    }
}

void Grader::chooseIsolation() {
    const bool root = ::geteuid() == 0;
    const int jobs = std::max(1, std::min<int>(config_.jobs, static_cast<int>(config_.submissions.size())));
    if (root && config_.isolation != "none") jobUids_ = pickJobUids(jobs);
    isolation_ = t10::grade::chooseIsolation(config_.isolation, jobUids_.empty() ? 0 : jobUids_.front(), "t10-grade", std::cerr);
    if (isolation_ == Isolation::None) {
        jobUids_.clear();
        return;
    }
    // Not root, every job runs as this user: its process limit must be counted in the job's own user
    // namespace, or a submission that forks until refused leaves the job beside it no process.
    std::string shared;
    if (jobUids_.empty()) shared = probeOwnProcessLimit();
    ownProcessLimit_ = jobUids_.empty() && shared.empty();
    std::cerr << "t10-grade: student code runs with isolation " << isolationName(isolation_);
    if (!jobUids_.empty()) {
        std::cerr << " (job uids";
        for (std::size_t i = 0; i < jobUids_.size(); ++i) std::cerr << (i ? "," : " ") << jobUids_[i];
        std::cerr << ")";
    } else if (ownProcessLimit_) {
        std::cerr << " (each job's process limit counted in its own user namespace)";
    }
    std::cerr << "\n";
    if (!shared.empty() && config_.jobs > 1) {
        std::cerr << "t10-grade: warning: the jobs cannot have process limits of their own here (" << shared
                  << "; the grader is not root, so there is no uid per job): a submission that forks until refused "
                     "would starve the one beside it, so submissions are graded one at a time (--jobs 1)\n";
        config_.jobs = 1;
    }
    if (isolation_ == Isolation::Uid) {
        struct stat info {};
        if (::stat(referenceStageDir().c_str(), &info) == 0 && (info.st_mode & S_IROTH)) {
            std::cerr << "t10-grade: warning: --isolation uid: " << referenceStageDir()
                      << " is readable by others, so student code can read the reference shaders (chmod o-rwx it)\n";
        }
    }
}

SandboxRun Grader::sandbox(int job, const SandboxLimits& limits) const {
    SandboxRun run;
    run.isolation = isolation_;
    run.uid = jobUids_.empty() ? 0 : jobUids_[static_cast<std::size_t>(job) % jobUids_.size()];
    run.ownProcessLimit = ownProcessLimit_;
    run.mounts = projectMounts_;
    run.limits = limits;
    return run;
}

std::string Grader::build(const std::string& source, int job, const fs::path& work, std::string& log) const {
    return buildProgram(kit_, info_.stage, config_.cacheDir, sandbox(job, kBuildLimits), source, work, log);
}

Report Grader::startReport(const std::string& submission, const std::string& name) const {
    Report report;
    report.submission = name;
    report.path = submission;
    report.part = config_.part;
    report.rubric = loadRubric(config_.part); // a faulty rubric stops before any build or render
    report.isolation = isolationName(isolation_);
    report.fill = fillPolicyName(config_.fill);
    return report;
}

fs::path Grader::makeJobFolder(uid_t uid) const {
    const fs::path work = workRoot_ / ("job" + uniqueSuffix());
    makeDir(work, 0, 0750);
    if (uid != 0 && ::chown(work.c_str(), 0, uid) != 0) throw Error(work.string() + ": chown: " + std::strerror(errno));
    return work;
}

bool Grader::copyIn(const std::string& submission, const Job& job, Report& report) const {
    const CopiedSubmission copied = copySubmission(fs::absolute(submission).string(), files_, referenceStageDir(),
                                                   config_.fill, job.shaders().string());
    report.files = copied.files;
    if (copied.empty) {
        report.status = Status::Empty;
        report.message = "the submission has no file of Part " + std::to_string(config_.part) +
                         " (see the file list: a name in the wrong case or a symlink is not taken)";
        return false;
    }
    if (!copied.missing.empty()) {
        report.status = Status::MissingFiles;
        report.message = "missing:";
        for (const std::string& file : copied.missing) report.message += " " + file;
        report.message += " (this part asks for them; the instructor's --fill-from-reference " +
                          std::string(fillPolicyName(config_.fill)) + " does not take them from the reference)";
        return false;
    }
    return true;
}

std::string Grader::buildSubmission(const Job& job, Report& report) const {
    std::string log;
    const std::string built = build((job.shaders() / "Tutorial10.cpp").string(), job.index, job.work, log);
    std::ofstream(job.out / "build.log") << studentPaths(log, job.work, report.submission);
    if (built.empty()) {
        report.status = Status::BuildFailed;
        report.message = "Tutorial10.cpp does not build against common/:\n" + studentPaths(lastLines(log, 40), job.work, report.submission);
    }
    return built;
}

fs::path Grader::stageProgram(const std::string& built, const Job& job) const {
    const uid_t uid = job.base.uid;
    // The job's copy of the program: the cache is not readable by its uid.
    const fs::path program = job.work / "student";
    copyFile(built, program, 0750);
    if (uid != 0 && ::chown(program.c_str(), 0, uid) != 0) throw Error(program.string() + ": chown: " + std::strerror(errno));
    // Its own Mesa shader cache, started from the grader's seed (the reference's shaders, compiled
    // when the reference rendered): what it writes there reaches no other submission.
    const fs::path mesa = job.work / "mesa-cache";
    const fs::path seed = fs::path(referenceDir_) / "mesa-seed";
    if (fs::is_directory(fs::symlink_status(seed))) copyTree(seed, mesa, uid);
    else makeDir(mesa, uid, 0700);
    makeDir(job.work / "tmp", uid, 0700);
    return program;
}

// The cases `specs` in one process (one case: a process of its own), logs in runs/<id>/run.log.
RunResult Grader::renderCases(const std::vector<CaseSpec>& specs, const Job& job, const fs::path& program) const {
    std::vector<CaseRender> renders;
    for (const CaseSpec& spec : specs) {
        const fs::path dir = caseDir(job, spec);
        std::error_code error;
        fs::remove_all(dir, error); // what an unfinished run of it left
        makeDir(dir, job.base.uid, 0700);
        std::string shaderDir = job.shaders().string();
        if (spec.id == "extremes") {
            const std::string probe = writeNanProbe(job.shaders().string(), (job.work / kNanProbeFolder).string());
            if (!probe.empty()) shaderDir = probe;
        }
        renders.push_back({spec.id, spec.args, shaderDir, dir});
    }
    if (specs.size() == 1) fs::create_directories(job.out / "runs" / specs.front().id);
    const fs::path log = specs.size() == 1 ? job.out / "runs" / specs.front().id / "run.log" : job.work / "cases.log";
    return runCases(job.base, program, publicInputs_, job.work, renders, config_.part == 3, log.string());
}

void Grader::reportFailedRun(const CaseSpec& spec, const RunResult& result, const Job& job, Report& report) const {
    const std::string& o = result.output;
    if (result.timedOut || result.signal == SIGXCPU) {
        report.status = Status::Timeout;
    } else if (result.signal == 0 && (o.find("shader compilation failed") != std::string::npos ||
                                      o.find("program link failed") != std::string::npos ||
                                      o.find("shader not found") != std::string::npos)) {
        report.status = Status::ShaderError;
    } else {
        report.status = Status::Crashed;
    }
    report.message = "case " + spec.id + " (" + spec.description + "): the program " + result.describe() +
                     (result.timedOut ? " (limit " + std::to_string(int(config_.timeout)) + " s)" : "") +
                     (result.signal == SIGXFSZ ? " (a file over the size limit)" : "") +
                     ". Its last output:\n" + studentPaths(lastLines(o, 30), job.work, report.submission);
}

// Every case in one process first (a process's start costs more than these small frames: about half
// of a submission's render time). A case that process did not finish, and each one after it, is then
// rendered alone, as it always was, so that a failure is the one that case's own process shows, with
// that process's whole time limit. Only a first case that ran out of time is not rendered again: its
// own process would have done exactly what this one did up to then.
bool Grader::captureCases(const Job& job, const fs::path& program, Report& report, std::vector<CaseRun>& runs) const {
    const std::vector<CaseSpec> specs = cases(config_.part);
    const RunResult together = renderCases(specs, job, program);
    const std::vector<std::string> logs = splitRunLog((job.work / "cases.log").string(), specs.size());
    // Case i finished when case i + 1 started (its marker), the last one when the process ended well.
    const std::size_t finished = together.ok() ? logs.size() : logs.size() - 1;
    for (std::size_t i = 0; i < specs.size(); ++i) {
        const CaseSpec& spec = specs[i];
        const bool done = i < finished;
        const bool firstTimedOut = i == 0 && !done && (together.timedOut || together.signal == SIGXCPU);
        if (done || firstTimedOut) {
            fs::create_directories(job.out / "runs" / spec.id);
            std::ofstream(job.out / "runs" / spec.id / "run.log", std::ios::binary) << logs[i];
        }
        if (firstTimedOut) {
            reportFailedRun(spec, together, job, report);
            return false;
        }
        if (!done) {
            const RunResult alone = renderCases({spec}, job, program);
            if (!alone.ok()) {
                reportFailedRun(spec, alone, job, report);
                return false;
            }
        }
        // Its outputs, as hostile files: every process of the run is dead, so they cannot change now.
        const fs::path dir = caseDir(job, spec);
        std::string fault = checkOutputs(dir);
        if (fault.empty()) fault = checkFrame((dir / "frame.png").string(), spec.width, spec.height);
        if (!fault.empty()) {
            report.status = Status::Crashed;
            report.message = "case " + spec.id + " (" + spec.description + "): the program exited 0 but " +
                             (fault.rfind("it ", 0) == 0 ? fault.substr(3) : "its output is unusable: " + fault);
            return false;
        }
        runs.push_back(CaseRun{spec.id, spec.description, spec.camera, CaseBuffers{}});
        try {
            runs.back().buffers = loadCaseBuffers(dir.string());
        } catch (const Error& error) {
            report.status = Status::Crashed;
            report.message = "case " + spec.id + ": the program exited 0 but wrote no readable output: " + error.what();
            return false;
        }
    }
    return true;
}

std::vector<Check> Grader::checkCase(const CaseSpec& spec, const CaseRun& run, const Job& job) const {
    ReportImages images(job.out.string(), (job.out / "images").string());
    // A buffer the part must write that is missing or malformed is one failed check saying which.
    std::vector<Check> checks = caseBufferChecks(config_.part, run, images);
    if (spec.camera) {
        Check flip = flipCheck(config_.part, run, referenceDir_ + "/" + spec.id + "/frame.png",
                               (caseDir(job, spec) / "frame.png").string(), job.out.string(), checks);
        // FLIP sees what a buffer check of the same case already blamed: it costs nothing more. Alone,
        // every buffer is right and the frame is not: it costs the steps that make the frame.
        const bool buffersFailed = std::any_of(checks.begin(), checks.end(), [](const Check& c) { return !c.passed; });
        if (!flip.passed && buffersFailed) {
            flip.followsFrom = true;
            std::string ids;
            for (const Check& c : checks)
                if (!c.passed) ids += (ids.empty() ? "" : ", ") + c.id;
            flip.diagnosis = "follows from " + ids + " (the frame shows what they diagnose)";
        }
        else if (!flip.passed) flip.blame = info_.frameSteps;
        checks.push_back(flip);
    }
    return checks;
}

void Grader::score(const std::vector<CaseRun>& runs, const Job& job, Report& report) const {
    report.status = Status::Graded;
    const std::vector<CaseSpec> specs = cases(config_.part);
    for (std::size_t i = 0; i < runs.size(); ++i) {
        const std::vector<Check> checks = checkCase(specs[i], runs[i], job);
        report.checks.insert(report.checks.end(), checks.begin(), checks.end());
    }
    crossCheckCases(config_.part, runs, report.checks);
}

// The pipeline of one submission: intake (the private copy), build, staging of the program, the
// renders of every case, then the checks and the score. Each step that fails sets the status and
// the message, and the report is written as it stands.
Report Grader::grade(const std::string& submission, const std::string& name, int job) const {
    const auto start = std::chrono::steady_clock::now();
    Report report = startReport(submission, name);
    const fs::path out = fs::absolute(config_.reportDir) / report.submission;
    fs::remove_all(out);
    fs::create_directories(out);

    // The job's private work folder: only the grader and the job's uid can enter it.
    const SandboxLimits renderLimits{config_.timeout, static_cast<int>(config_.timeout * 2) + 5, 4096, 64, 256, 64, 64};
    const SandboxRun base = sandbox(job, renderLimits);
    const Job folders{job, out, makeJobFolder(base.uid), base};
    struct Cleanup {
        fs::path dir;
        ~Cleanup() {
            std::error_code error;
            fs::remove_all(dir, error);
        }
    } cleanup{folders.work};
    // Reports are written only here, after every process of the submission is dead (runSandboxed
    // returns only then).
    auto finish = [&](Report& r) {
        r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        writeReportJson(r, (out / "report.json").string());
        writeReportHtml(r, (out / "report.html").string());
        return r;
    };

    if (!copyIn(submission, folders, report)) return finish(report);
    const std::string built = buildSubmission(folders, report);
    if (built.empty()) return finish(report);
    const fs::path program = stageProgram(built, folders);
    std::vector<CaseRun> runs;
    if (!captureCases(folders, program, report, runs)) return finish(report);
    score(runs, folders, report);
    return finish(report);
}

// What every submission gets when the grader fails before or beside grading it: status grader-error,
// in report.json and every platform's result, where its report folder is known and writable.
Report graderError(const Config& config, std::size_t i, const std::string& why, const std::string& isolation) {
    Report report;
    report.submission = config.names[i];
    report.path = config.submissions[i];
    report.part = config.part;
    report.status = Status::GraderError;
    report.isolation = isolation;
    report.fill = fillPolicyName(config.fill);
    report.message = "the grader failed: " + why;
    return report;
}

// Writes report.json and the platforms' results of one report; a failure is one line on stderr.
bool writeResults(const Config& config, const Report& report, std::ostream& log) {
    try {
        const fs::path dir = fs::path(config.reportDir) / report.submission;
        if (report.status == Status::GraderError) {
            fs::create_directories(dir);
            writeReportJson(report, (dir / "report.json").string());
        }
        writeFormats(report, config.formats, dir.string());
        return true;
    } catch (const std::exception& error) {
        log << "t10-grade: error: writing the results of " << report.path << ": " << errorLine(error) << "\n";
    } catch (...) {
        log << "t10-grade: error: writing the results of " << report.path << ": an unknown exception\n";
    }
    return false;
}

// Grades every submission of `config` with grader.jobs() threads (config.jobs, or 1 where the jobs cannot
// have process limits of their own); returns the exit code.
int gradeAll(const Config& config) {
    const Grader grader(config);
    std::vector<Report> reports(config.submissions.size());
    std::atomic<std::size_t> next{0};
    std::atomic<bool> failed{false};
    std::mutex printing;
    auto worker = [&](int job) {
        for (std::size_t i = next++; i < config.submissions.size(); i = next++) {
            std::string why;
            try {
                reports[i] = grader.grade(config.submissions[i], config.names[i], job);
                const std::lock_guard<std::mutex> lock(printing);
                std::cout << reports[i].submission << ": " << statusName(reports[i].status) << ", score " << reports[i].score()
                          << " (" << reports[i].passedCount() << "/" << reports[i].checks.size() << " checks) in "
                          << static_cast<int>(reports[i].seconds + 0.5) << " s\n";
            } catch (const std::exception& error) {
                why = errorLine(error);
            } catch (...) {
                why = "an unknown exception";
            }
            const std::lock_guard<std::mutex> lock(printing);
            if (!why.empty()) {
                std::cerr << "t10-grade: error: grading " << config.submissions[i] << ": " << why << "\n";
                reports[i] = graderError(config, i, why, isolationName(grader.isolation()));
                failed = true;
            }
            if (!writeResults(config, reports[i], std::cerr)) failed = true;
        }
    };
    // The threads are joined whatever happens: a std::thread destroyed while joinable ends the process.
    struct Joined {
        std::vector<std::thread> threads;
        ~Joined() {
            for (std::thread& t : threads)
                if (t.joinable()) t.join();
        }
    } jobs;
    try {
        for (int j = 0; j < std::min<int>(grader.jobs(), static_cast<int>(config.submissions.size())); ++j)
            jobs.threads.emplace_back(worker, j);
    } catch (const std::system_error& error) {
        // Under a process limit: the threads started share the rest (the main thread when none did).
        std::cerr << "t10-grade: warning: started " << jobs.threads.size() << " of " << grader.jobs()
                  << " job threads (" << error.code().message() << "); the others' submissions wait for them\n";
        if (jobs.threads.empty()) worker(0);
    }
    for (std::thread& t : jobs.threads) t.join();
    const std::string gradebook = (fs::path(config.reportDir) / "gradebook.csv").string();
    writeGradebook(reports, gradebook);
    std::string similarity;
    if (config.similarity) {
        try {
            similarity = compareClass(config.part, config.submissions, config.names, config.reportDir, config.similarityThreshold);
        } catch (const std::exception& error) {
            std::cerr << "t10-grade: error: " << errorLine(error) << "\n";
            similarity = "<h2>Pairs to review</h2>\n<p>The comparison failed: " + htmlEscape(errorLine(error)) + "</p>\n";
            failed = true;
        }
    }
    writeClassIndex(reports, config.studentNames, config.reportDir, similarity);
    std::cout << "wrote " << gradebook << ", index.html, grades-lms.csv and a report per submission in " << config.reportDir << "/\n";
    // A submission the grader could not grade (status grader-error in the gradebook) is the
    // grader's failure, not the student's.
    return failed ? 1 : 0;
}

} // namespace

// Every exception ends here: one line on stderr naming what failed (a path and the system's reason
// for a system error), and a grader-error result for each submission whose report folder is known.
int main(int argc, char** argv) {
    Config config;
    try {
        parse(argc, argv, config);
        return gradeAll(config);
    } catch (const UsageError& error) {
        std::cerr << "t10-grade: error: " << error.what() << "\n" << kUsage;
        return 2;
    } catch (...) {
        const std::string why = errorLine(std::current_exception());
        std::cerr << "t10-grade: error: " << why << "\n";
        // The platforms still get a result for each submission: the grader's failure, not the student's.
        // Where the first cannot be written (the report folder is what failed) the rest are not tried.
        for (std::size_t i = 0; i < config.names.size() && i < config.submissions.size(); ++i)
            if (!writeResults(config, graderError(config, i, why, config.isolation), std::cerr)) break;
        return 1;
    }
}
