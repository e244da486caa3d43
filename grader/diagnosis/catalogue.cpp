// Parsing the mistake catalogue and looking mistakes up; see catalogue.hpp. Reading it from its file
// is catalogue_file.cpp's.
#include "diagnosis/catalogue.hpp"

#include "t10/error.hpp"

#include <sstream>

namespace t10::grade {

namespace {

std::vector<std::string> split(const std::string& line, char separator) {
    std::vector<std::string> fields;
    std::stringstream in(line);
    for (std::string field; std::getline(in, field, separator);) fields.push_back(field);
    return fields;
}

} // namespace

std::vector<Mistake> parseCatalogue(std::istream& in, const std::string& path) {
    std::vector<Mistake> table;
    int number = 0;
    for (std::string line; std::getline(in, line);) {
        ++number;
        if (line.empty() || line[0] == '#') continue;
        const std::vector<std::string> fields = split(line, '\t');
        const std::string where = path + ":" + std::to_string(number) + ": ";
        if (fields.size() != 5) throw Error(where + "expected 5 tab-separated fields, found " + std::to_string(fields.size()));
        Mistake m;
        m.id = fields[0];
        m.parameter = fields[1] == "-" ? "" : fields[1];
        try {
            if (fields[2] != "-")
                for (const std::string& v : split(fields[2], ' ')) {
                    m.tutorial.push_back(std::stod(v));
                    m.tutorialText.push_back(v);
                }
            for (const std::string& s : split(fields[3], ' ')) m.steps.push_back(std::stoi(s));
        } catch (const std::exception&) {
            throw Error(where + "the value '" + fields[2] + "' or the steps '" + fields[3] + "' are not numbers");
        }
        m.text = fields[4];
        if (m.steps.empty()) throw Error(where + "no steps");
        table.push_back(std::move(m));
    }
    return table;
}

const Mistake& mistake(const std::string& id) {
    for (const Mistake& m : catalogue())
        if (m.id == id) return m;
    throw Error(catalogueName() + ": no mistake '" + id + "' (the grader names it)");
}

} // namespace t10::grade
