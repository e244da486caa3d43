// Reading the rubric; see rubric.hpp.
#include "scoring/rubric.hpp"

#include "part/part.hpp"
#include "t10/error.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <vector>

namespace t10::grade {

std::string rubricPath() {
    const char* path = std::getenv("T10_GRADE_RUBRIC");
    return path != nullptr && *path != '\0' ? path : T10_GRADE_RUBRIC_DEFAULT;
}

Rubric loadRubric(int part) {
    const std::string path = rubricPath();
    std::ifstream in(path);
    if (!in) throw Error(path + ": cannot open the rubric: " + std::strerror(errno));
    double fallback = 1.0;
    std::map<int, double> listed;
    int number = 0;
    for (std::string line; std::getline(in, line);) {
        ++number;
        const auto hash = line.find('#');
        if (hash != std::string::npos) line.erase(hash);
        std::istringstream fields(line);
        std::string what;
        double points = 0.0;
        if (!(fields >> what)) continue;
        std::string extra;
        const std::string where = path + ":" + std::to_string(number) + ": ";
        if (!(fields >> points) || points < 0.0 || (fields >> extra))
            throw Error(where + "expected STEP POINTS, FIRST-LAST POINTS or default POINTS (points >= 0)");
        if (what == "default") {
            fallback = points;
            continue;
        }
        int first = 0, last = 0;
        char dash = 0;
        std::istringstream range(what);
        if (!(range >> first)) throw Error(where + "'" + what + "' is not a step number");
        last = first;
        if (range >> dash && (dash != '-' || !(range >> last))) throw Error(where + "'" + what + "' is not FIRST-LAST");
        if (first < 1 || last < first) throw Error(where + "'" + what + "' is not a step range");
        for (int step = first; step <= last; ++step) listed[step] = points;
    }
    Rubric rubric;
    double total = 0.0;
    for (int step : partInfo(part).steps) {
        const auto at = listed.find(step);
        rubric[step] = at == listed.end() ? fallback : at->second;
        total += rubric[step];
    }
    if (!(total > 0.0)) throw Error(path + ": the steps of Part " + std::to_string(part) + " are worth 0 points");
    return rubric;
}

std::map<int, int> wholePoints(const Rubric& listed, int part) {
    Rubric rubric;
    for (int step : partInfo(part).steps) {
        const auto at = listed.find(step);
        rubric[step] = at == listed.end() ? 1.0 : at->second;
    }
    double total = 0.0;
    for (const auto& [step, points] : rubric) total += points;
    std::map<int, int> whole;
    if (!(total > 0.0)) {
        for (const auto& entry : rubric) whole[entry.first] = 0;
        return whole;
    }
    // (remainder in units of 1e-9, step): equal shares tie exactly, whatever their last bits.
    std::vector<std::pair<long long, int>> remainders;
    int given = 0;
    for (const auto& [step, points] : rubric) {
        const double share = 100.0 * points / total;
        // The 1e-9 keeps an exact share (6.25 * 16 = 100) from losing a point to its last bit.
        const int floor = static_cast<int>(std::floor(share + 1e-9));
        whole[step] = floor;
        given += floor;
        remainders.emplace_back(std::llround((share - floor) * 1e9), step);
    }
    std::stable_sort(remainders.begin(), remainders.end(),
                     [](const auto& a, const auto& b) { return a.first > b.first; });
    for (std::size_t i = 0; given < 100 && i < remainders.size(); ++i, ++given) ++whole[remainders[i].second];
    return whole;
}

} // namespace t10::grade
