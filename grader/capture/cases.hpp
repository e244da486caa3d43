// The cases every submission renders (two scene views, two synthetic inputs), the synthetic inputs
// themselves, and the reference stage's renders of the cases, which the checks compare against.
// Inputs and reference renders are kept in the grader's cache while their manifests hold.
#pragma once
#include <filesystem>
#include <string>
#include <vector>

namespace t10::grade {

struct CaseSpec {
    std::string id;
    std::string description;
    bool camera;
    std::vector<std::string> args; // "{inputs}" is replaced by the synthetic inputs' folder
    int width;                     // of the frame the case must write
    int height;
};

// How llvmpipe renders the reference's and every submission's cases: without LLVM's optimisation
// passes and with 128-bit vectors. For frames this small compiling the shaders costs more than drawing
// them: a Part 3 case takes 0.15 CPU s with a warm shader cache instead of 0.36 (0.33 instead of 0.63
// cold), and every output is the same bits (tests/llvmpipe/same_bits.sh; every case of every stage,
// Mesa 22.3 and 25.0). Large frames draw slower with 128-bit vectors: not for make run or the site.
// The frames are drawn in the program's own thread (LP_NUM_THREADS=0): a 128x128 case is a few tiles,
// and starting and waking rasterizer threads cost more than they draw (Part 3's pot case: 0.29-0.32 CPU
// s instead of 0.33-0.40 with two threads, and less wall time too; the same bits, same_bits.sh). The
// jobs run side by side anyway, and a job's process limit no longer counts llvmpipe's threads.
inline const std::vector<std::string> kLlvmpipeSmallRenders{"GALLIVM_PERF=nopt", "LP_NATIVE_VECTOR_WIDTH=128", "LP_NUM_THREADS=0"};

// The cases of Part `part` (1, 2 or 3), in the order they are rendered and reported.
std::vector<CaseSpec> cases(int part);
// A case's arguments with "{inputs}" replaced by the synthetic inputs' folder `inputs`.
std::vector<std::string> caseArgs(const std::vector<std::string>& args, const std::string& inputs);

// The synthetic inputs (make_test_images) in `cacheDir`/inputs, made when absent or no longer
// matching their manifest; copies them to `publicInputs` (absent), readable by the jobs. Returns the
// cached folder. Throws t10::Error when they cannot be made.
std::string prepareInputs(const std::string& cacheDir, const std::filesystem::path& publicInputs);

// The reference stage's renders of the cases of `part` (`referenceBinary`, whose `shaders` are in
// `stageDir`) in `cacheDir`, rendered outside the sandbox (trusted code) unless a folder of the same
// program and shaders whose manifest holds is there; its Mesa shader cache is kept as mesa-seed.
// Returns that folder. Throws t10::Error when the reference fails.
std::string renderReference(const std::string& referenceBinary, const std::string& stage,
                            const std::vector<std::string>& shaders, const std::string& stageDir, const std::string& cacheDir,
                            const std::string& inputsDir, int part);

} // namespace t10::grade
