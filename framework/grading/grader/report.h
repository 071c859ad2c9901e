// What the grader writes: the table students and instructors read (plain text and Markdown), JSON
// feedback, JUnit XML, Gradescope's results.json, and the class gradebook in clothlab's own CSV and in
// the import formats of Moodle and Canvas. Every total comes from totals() (common.h).
#pragma once
#include <set>

#include "common.h"

namespace grade {

/// The per-stage table; with `verbose` every failed test and why (its first 8 lines).
void printTable(const std::vector<StageResult>& stages, bool verbose);
/// clothlab's own JSON: per stage its status, points and tests (./lab grade --json, feedback/NAME.json).
json resultsJson(const std::vector<StageResult>& stages);
/// The stages of resultsJson() read back (a class's cached results).
std::vector<StageResult> resultsFromJson(const json& j);
/// JUnit XML: one testsuite per stage, one testcase per graded test, the points as properties.
void writeJunit(const fs::path& path, const std::vector<StageResult>& stages, const std::string& suite_prefix = "");
/// Gradescope's autograder results.json (https://gradescope-autograders.readthedocs.io/en/latest/specs/):
/// top-level score, execution_time (seconds), output, stdout_visibility; one entry in `tests` per graded
/// test with name, score, max_score, status (passed/failed), output (why it failed), visibility and
/// name_format. A stage that could not be graded (does not compile, rejected, not submitted) keeps its
/// tests, each failed with the stage's problem (the compiler's message) as its output.
json gradescopeJson(const std::vector<StageResult>& stages, double execution_seconds);
/// The per-stage table as Markdown (GitHub's job summary, ./lab grade --markdown): one row per stage,
/// the total, then every failed test with the first lines of its message.
std::string markdownTable(const std::vector<StageResult>& stages);
/// "ok" or what kept stages from being graded ("01 does not compile; 03 rejected").
std::string statusLine(const std::vector<StageResult>& stages);

/// One student of a class: the identifier (the folder or archive name) and the stages' points.
struct GradebookRow {
    std::string student, status;
    std::vector<StageResult> stages;
};
/// A class's gradebooks, one row per student: `gradebook.csv` (student, a column per stage, total, max,
/// status, bonus); Moodle's grade import `moodle.csv` (Grades > Import > CSV file: "Identifier", mapped
/// on import to username, email address or ID number, then a column per grade item); Canvas's
/// `canvas.csv` (Grades > Import: Student, ID, SIS User ID, Section, a column per assignment, a "Points
/// Possible" row as in Canvas's own export; the identifier fills Student and SIS User ID). The import
/// formats have a column per graded stage only (`only`, empty: all), named "clothlab NN title".
void writeGradebooks(const fs::path& out, const std::vector<std::string>& stages, const std::set<std::string>& only,
                     const fs::path& points_dir, const std::vector<GradebookRow>& rows);

}  // namespace grade
