// The pictures of a failed frame check, written into a submission's report folder: the student's
// frame, the expected one and their difference heat-map, named in the check relative to the report.
#pragma once
#include "checks/checks.hpp"

#include <string>

namespace t10::grade {

class ReportImages : public CheckImages {
public:
    // Writes into `imageDir` (a folder inside `reportDir`, made when the first picture comes).
    ReportImages(std::string reportDir, std::string imageDir);
    void attach(Check& check, const Image8& student, const Image8& expected) override;

private:
    std::string relative(const std::string& path) const;
    std::string reportDir_;
    std::string imageDir_;
};

} // namespace t10::grade
