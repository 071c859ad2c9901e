// Grading a whole class: one folder or archive per student, graded in parallel, a gradebook.
#pragma once
#include "submission.h"

namespace grade {

/// What gradeClass() grades, where its files go and how many students at a time.
struct ClassOptions {
    fs::path class_dir;  ///< one folder or .zip/.tar.gz/.tgz/.tar per student
    fs::path out;        ///< gradebook.csv, moodle.csv, canvas.csv, feedback/NAME.json, junit/NAME.xml, writeups/NAME/, .work/ (cache)
    int jobs = 1;        ///< students graded at the same time
    GradeOptions grade;  ///< per student (its jobs and work are set here)
};

/// Grades every submission; a broken or hostile submission costs that student only. A student whose
/// files did not change since the last run keeps the results of that run.
void gradeClass(const Kit& kit, const ClassOptions& options);

}  // namespace grade
