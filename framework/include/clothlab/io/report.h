/// @file report.h
/// @brief The run report: error metrics beside wall time, as text, CSV and JSON.
#pragma once
#include <ostream>
#include <string>

#include "clothlab/sim/run.h"

namespace clothlab {

/// Prints the report's header line (column names with units) for the first row's metrics.
void printReportHeader(std::ostream& out, const ReportRow& first);

/// Prints one report row: step, simulated time, wall time, every metric.
void printReportRow(std::ostream& out, const ReportRow& row);

/// Prints the summary: steps, simulated and wall time, time per step, why the run stopped (if it
/// did), the final metrics, the worst penetration over the whole run (scenes with colliders), with a
/// MetricWindow every metric's min, mean and max over it (WindowStat), every
/// warning (warningText(): what, since which step, what would help) and the table of passes that
/// ran (wall time, calls, share).
void printSummary(std::ostream& out, const Simulation& sim, const RunResult& result);

/// Writes the report rows as CSV with units in the header: `step,t [s],wall [s],<metric> [<unit>],...`.
/// @throws InputError if the file cannot be written
void writeReportCsv(const std::string& path, const RunResult& result);

/// Writes the summary (scene, method, dt, steps, wall time, `cause` of a stop (causeName()), final
/// metrics with `worst_penetration` {value, unit, step}, with a MetricWindow `window` {from, to,
/// states, metrics: {name: {min, mean, max, unit}}}, `warnings` [{kind, step, t, value, message,
/// collider, particle, particles}], pass timings) as JSON.
/// @throws InputError if the file cannot be written
void writeSummaryJson(const std::string& path, const Simulation& sim, const RunResult& result);

/// Writes the state as CSV with the header `i,x,y,z,vx,vy,vz`, one row per particle. Every file
/// the report writes prints doubles with 17 significant digits, so that they read back bit for bit.
/// @throws InputError if the file cannot be written
void writeStateCsv(const std::string& path, const State& state);

/// Reads positions x (m) and velocities v (m/s) from a state CSV written by writeStateCsv() into
/// `state`, which must have as many particles as the file has rows; inverse masses and time stay.
/// Row k must be particle k. A state written and read back is bit-identical.
/// @throws InputError naming the file and the row or field for a missing or wrong header, a row
///         that is not 7 numbers, an index out of order, a NaN or infinite value, or a wrong row count
void readStateCsv(const std::string& path, State& state);

}  // namespace clothlab
