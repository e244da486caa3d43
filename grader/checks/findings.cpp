// The findings of a check; see findings.hpp.
#include "checks/findings.hpp"

#include "diagnosis/model.hpp"

#include <algorithm>
#include <set>
#include <sstream>

namespace t10::grade {

namespace {

// The student's value to the precision the tutorial writes its own with ("0.2126" -> 4 decimals; a
// value written with an exponent, "1e-8", keeps its significant digits), or 3 significant digits.
std::string likeWritten(double value, const std::string& written) {
    if (written.find_first_of("eE") != std::string::npos || written.empty()) return format(value, 3);
    const std::size_t dot = written.find('.');
    const int decimals = dot == std::string::npos ? 0 : static_cast<int>(written.size() - dot - 1);
    std::ostringstream text;
    text.setf(std::ios::fixed);
    text.precision(decimals);
    text << value;
    return text.str();
}

std::string listed(const std::vector<std::string>& values) {
    if (values.size() == 1) return values[0];
    std::string out = "(";
    for (std::size_t i = 0; i < values.size(); ++i) out += (i ? ", " : "") + values[i];
    return out + ")";
}

// "your luminance weights measure (0.2130, 0.7150, 0.0720); the tutorial's are (0.2126, 0.7152, 0.0722)":
// the tutorial's values as mistakes.tsv writes them, the student's to the same decimals.
std::string estimateText(const Mistake& m, const std::vector<double>& value) {
    std::string words = m.parameter;
    std::replace(words.begin(), words.end(), '_', ' ');
    const bool plural = words.size() > 1 && words.back() == 's' && words[words.size() - 2] != 's';
    std::vector<std::string> student;
    for (std::size_t i = 0; i < value.size(); ++i)
        student.push_back(likeWritten(value[i], i < m.tutorialText.size() && value.size() == m.tutorialText.size()
                                                    ? m.tutorialText[i] : std::string()));
    return "your " + words + (plural ? " measure " : " measures ") + listed(student) + "; the tutorial's " +
           (plural ? "are " : "is ") + listed(m.tutorialText);
}

} // namespace

std::string stepRange(const std::vector<int>& steps) {
    if (steps.size() == 1) return "step " + std::to_string(steps[0]);
    const bool contiguous = steps.back() - steps.front() + 1 == int(steps.size());
    if (contiguous) return "steps " + std::to_string(steps.front()) + "\u2013" + std::to_string(steps.back());
    std::string out = "steps ";
    for (std::size_t i = 0; i < steps.size(); ++i) out += (i ? ", " : "") + std::to_string(steps[i]);
    return out;
}

std::string findingText(const std::string& id, const std::vector<int>& steps, const std::vector<double>& value,
                        const std::string& note) {
    const Mistake& m = mistake(id);
    std::string text = "[" + id + "] ";
    if (!m.parameter.empty() && !value.empty()) {
        text += estimateText(m, value);
    } else if (id.size() > 8 && id.compare(id.size() - 8, 8, "-missing") == 0 && steps.size() > 1) {
        text += stepRange(steps) + " not implemented: " + m.text;
    } else {
        text += m.text;
    }
    if (!note.empty()) text += " (" + note + ")";
    return text + " (" + stepRange(steps) + ")";
}

void name(Check& check, const std::string& id, const std::vector<int>& steps, const std::vector<double>& value,
          const std::string& note, bool loose) {
    const Mistake& m = mistake(id);
    for (int step : steps)
        if (std::find(check.blame.begin(), check.blame.end(), step) == check.blame.end()) check.blame.push_back(step);
    std::sort(check.blame.begin(), check.blame.end());
    const std::string text = findingText(id, steps, value, note);
    check.mistakes.push_back(Finding{id, m.parameter, value, m.tutorial, steps, text, loose});
    check.diagnosis += (check.diagnosis.empty() ? "" : "; or ") + text;
}

void rebuildDiagnosis(Check& check) {
    check.blame.clear();
    if (check.mistakes.empty()) {
        check.diagnosis = check.unexplained;
        check.blame = check.unexplainedBlame;
        return;
    }
    check.diagnosis = check.mistakes.size() > 1 ? "one of: " : "";
    for (std::size_t i = 0; i < check.mistakes.size(); ++i) {
        check.diagnosis += (i ? "; or " : "") + check.mistakes[i].text;
        for (int step : check.mistakes[i].steps)
            if (std::find(check.blame.begin(), check.blame.end(), step) == check.blame.end()) check.blame.push_back(step);
    }
    std::sort(check.blame.begin(), check.blame.end());
}

void chargeOneStep(Check& check, const std::string& what, int step, const std::vector<int>& lookMissing) {
    std::set<int> charged(lookMissing.begin(), lookMissing.end());
    charged.insert(step);
    check.unexplainedBlame.assign(charged.begin(), charged.end());
    check.unexplained = what + "; it costs " +
                        (lookMissing.empty() ? "one step, step " + std::to_string(step) + ": one mistake that no model places among " +
                                                   stepRange(check.steps)
                                             : stepRange(check.unexplainedBlame) + ": it is nearer to " + stepRange(lookMissing) +
                                                   " not done than to the tutorial's, and step " + std::to_string(step) +
                                                   " for what else is wrong");
    rebuildDiagnosis(check);
}

void keepFindings(Check& check, const std::function<bool(const Finding&)>& keep) {
    std::vector<Finding> kept;
    for (const Finding& f : check.mistakes)
        if (keep(f)) kept.push_back(f);
    if (kept.empty() || kept.size() == check.mistakes.size()) return;
    check.mistakes = kept;
    rebuildDiagnosis(check);
}

bool names(const Check& c, const std::string& id) {
    return std::any_of(c.mistakes.begin(), c.mistakes.end(), [&](const Finding& f) { return f.id == id; });
}

void drop(Check& c, const std::string& id) {
    c.mistakes.erase(std::remove_if(c.mistakes.begin(), c.mistakes.end(), [&](const Finding& f) { return f.id == id; }),
                     c.mistakes.end());
}

std::vector<int> failedSteps(const Check& check) {
    if (check.passed || check.followsFrom) return {};
    return check.blame.empty() ? check.steps : check.blame;
}

} // namespace t10::grade
