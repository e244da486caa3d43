// Writing a failed check's pictures; see check_images.hpp.
#include "report/check_images.hpp"

#include "t10/compare.hpp"
#include "t10/image_io.hpp"

#include <filesystem>

namespace t10::grade {

ReportImages::ReportImages(std::string reportDir, std::string imageDir)
    : reportDir_(std::move(reportDir)), imageDir_(std::move(imageDir)) {}

void ReportImages::attach(Check& check, const Image8& student, const Image8& expected) {
    std::filesystem::create_directories(imageDir_);
    const std::string base = (std::filesystem::path(imageDir_) / check.id).string();
    t10::writePng(base + ".student.png", student);
    t10::writePng(base + ".expected.png", expected);
    t10::writePng(base + ".diff.png", t10::test::differenceHeatMap(expected, student));
    check.studentImage = relative(base + ".student.png");
    check.referenceImage = relative(base + ".expected.png");
    check.heatMap = relative(base + ".diff.png");
}

std::string ReportImages::relative(const std::string& path) const {
    return std::filesystem::relative(path, reportDir_).generic_string();
}

} // namespace t10::grade
