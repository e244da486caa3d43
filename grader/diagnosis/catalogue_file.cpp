// The mistake catalogue read from its file, grader/diagnosis/mistakes.tsv (T10_GRADE_MISTAKES); see
// catalogue.hpp.
#include "diagnosis/catalogue.hpp"

#include "t10/error.hpp"

#include <cerrno>
#include <cstring>
#include <fstream>

namespace t10::grade {

const std::string& catalogueName() {
    static const std::string name = T10_GRADE_MISTAKES;
    return name;
}

const std::vector<Mistake>& catalogue() {
    static const std::vector<Mistake> table = [] {
        std::ifstream in(catalogueName());
        if (!in) throw Error(catalogueName() + ": cannot open the mistake catalogue: " + std::strerror(errno));
        return parseCatalogue(in, catalogueName());
    }();
    return table;
}

} // namespace t10::grade
