// The mistake catalogue of t10-grade, read from grader/diagnosis/mistakes.tsv (the one table the grader,
// its tests and the instructors' page share), and the findings a check reports from it.
#pragma once
#include <istream>
#include <string>
#include <vector>

namespace t10::grade {

struct Mistake {
    std::string id;          // "white-point"
    std::string parameter;   // "white_point", or "" for a mistake without a value
    std::vector<double> tutorial; // the tutorial's value (empty without a parameter)
    std::vector<std::string> tutorialText; // the same, as the tutorial (and mistakes.tsv) writes it
    std::vector<int> steps;  // the steps it can be made in
    std::string text;        // what a student reads
};

// A mistake a check named: its fitted value where it has a parameter, and the steps it costs.
struct Finding {
    std::string id;
    std::string parameter;
    std::vector<double> value;
    std::vector<double> tutorial;
    std::vector<int> steps;
    std::string text; // the sentence of the diagnosis that names it
    // The tolerance also holds 7 % either side of the value: the case does not pin it down, and
    // crossCheckCases takes the value a case that does pin it measured.
    bool loose = false;
};

// The table, loaded once: catalogue_file.cpp reads the file T10_GRADE_MISTAKES, throwing t10::Error
// naming the file and line on a fault (a page would parse the text it was given). catalogueName names
// where it came from in messages.
const std::vector<Mistake>& catalogue();
const std::string& catalogueName();
// Parses the table's text (mistakes.tsv's format); `name` and the line number name a fault.
std::vector<Mistake> parseCatalogue(std::istream& in, const std::string& name);
// The entry `id`; throws t10::Error for an id the table lacks (a grader bug, not a student's).
const Mistake& mistake(const std::string& id);

} // namespace t10::grade
