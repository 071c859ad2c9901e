// What the grader writes: the table students and instructors read, JSON feedback, JUnit XML, the
// GitHub Classroom reporter's format, and the class gradebook.
#pragma once
#include <string>
#include <vector>

#include "common.h"

namespace grade {

/// The per-stage table; with `verbose` every failed test and why (its first `lines` lines).
void printTable(const std::vector<StageResult>& stages, bool verbose, int lines = 8);
json resultsJson(const std::vector<StageResult>& stages);
void writeJunit(const fs::path& path, const std::vector<StageResult>& stages, const std::string& suite_prefix = "");
/// The JSON that GitHub Classroom's autograding-grading-reporter reads (base64 in <ID>_RESULTS).
json classroomJson(const std::vector<StageResult>& stages);
/// The hints taken, "1.1:2 4.3:1" (task: levels), "" when none.
std::string hintsText(const std::vector<StageResult>& stages);
/// "ok" or what kept stages from being graded ("01 does not compile; 03 rejected").
std::string statusLine(const std::vector<StageResult>& stages);

}  // namespace grade
