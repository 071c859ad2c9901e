// What the grader writes: the table students and instructors read (plain text and Markdown), JSON
// feedback, JUnit XML, Gradescope's results.json, and the class gradebook in clothlab's own CSV and in
// the import formats of Moodle and Canvas.
#pragma once
#include <string>
#include <vector>

#include "common.h"

namespace grade {

/// The per-stage table; with `verbose` every failed test and why (its first `lines` lines).
void printTable(const std::vector<StageResult>& stages, bool verbose, int lines = 8);
/// clothlab's own JSON: per stage its status, points and tests (./lab grade --json, feedback/NAME.json).
json resultsJson(const std::vector<StageResult>& stages);
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

/// One column of a class gradebook: a stage as a grade item (Moodle) or assignment (Canvas).
struct GradeItem {
    std::string stage;  ///< "01"
    std::string name;   ///< "clothlab 01 Hooke spring and time integration"
    double max_points = 0;
};
/// One student of a class: the identifier (the folder or archive name) and the stages' points.
struct GradebookRow {
    std::string student;
    std::vector<StageResult> stages;
};
/// Moodle's grade import (Grades > Import > CSV file): a header row, then one row per student: the
/// identifier column "Identifier" (mapped on import to username, email address or ID number) and one
/// column per grade item with the points.
std::string moodleCsv(const std::vector<GradeItem>& items, const std::vector<GradebookRow>& rows);
/// Canvas's gradebook import (Grades > Import): the columns Student, ID, SIS User ID, Section, then one
/// per assignment; a "Points Possible" row (as in Canvas's own export) gives each assignment's maximum.
/// The identifier fills Student and SIS User ID; ID (Canvas's internal user id) and Section stay empty.
std::string canvasCsv(const std::vector<GradeItem>& items, const std::vector<GradebookRow>& rows);
/// A CSV field: quoted (with "" for ") when it holds a comma, quote or line break; line breaks become spaces.
std::string csvField(const std::string& s);
/// A number for a CSV cell: %g (43, 21.5).
std::string csvNumber(double x);
/// The points of `stage` in a student's results (0 when the stage is not among them).
double stagePoints(const std::vector<StageResult>& stages, const std::string& stage);
/// "ok" or what kept stages from being graded ("01 does not compile; 03 rejected").
std::string statusLine(const std::vector<StageResult>& stages);

}  // namespace grade
