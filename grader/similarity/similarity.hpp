// t10-grade --similarity: after a class is graded, the pairs of students who share work beyond what the
// course hands out, found by JPlag through grader/similarity/similarity.py (which writes
// similarity.json, .csv and .html into the report folder), and the class index's section of them.
#pragma once
#include <string>
#include <vector>

namespace t10::grade {

// "" when JPlag (make similarity-deps) and Java are installed, else what is missing and how to install it.
std::string similarityEngineProblem();

// Compares the class's submissions (each with its report folder's name) of `part`; threshold < 0 lets the
// class's distribution set it. Returns the class index's section (HTML): the pairs to review with their
// side-by-side pages. Throws t10::Error naming the fault when the comparison fails. Student code is only
// read, never run, so nothing here needs the sandbox.
std::string compareClass(int part, const std::vector<std::string>& submissions, const std::vector<std::string>& names,
                         const std::string& reportDir, double threshold);

} // namespace t10::grade
