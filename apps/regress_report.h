#pragma once
// What `eikon regress` tells beyond its lines: an HTML page for people (each failed image as
// reference, new image and a heat map of the difference; each failed grid's worst voxels; each
// error's reason and the end of its log) and JUnit XML for CI systems (GitLab, Jenkins and GitHub
// read it).
#include <string>
#include <vector>

#include "apps/regress_check.h"

namespace eikon::app {

enum class CaseStatus { Pass, Fail, Error, Updated };

struct CaseResult {
    std::string name;
    std::string description;
    CaseStatus status = CaseStatus::Error;
    std::string reason;  // one line: the first finding, or why the case could not run
    std::vector<Finding> findings;
    double seconds = 0.0;
    std::string logPath;  // the case's commands and their output
};

const char* statusWord(CaseStatus s);  // "pass", "FAIL", "ERROR", "updated"

// Writes `dir`/index.html and its pictures under `dir`/images/. Throws eikon::Error naming the
// file it could not write.
void writeHtmlReport(const std::string& dir, const std::string& suite,
                     const std::vector<CaseResult>& results, double seconds);

void writeJUnit(const std::string& path, const std::string& suite,
                const std::vector<CaseResult>& results, double seconds);

}  // namespace eikon::app
