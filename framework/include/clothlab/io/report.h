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

/// Prints the summary: steps, simulated and wall time, time per step, and the table of
/// passes that ran (wall time, calls, share).
void printSummary(std::ostream& out, const Simulation& sim, const RunResult& result);

/// Writes the report rows as CSV with units in the header: `step,t [s],wall [s],<metric> [<unit>],...`.
/// @throws InputError if the file cannot be written
void writeReportCsv(const std::string& path, const RunResult& result);

/// Writes the summary (scene, method, dt, steps, wall time, final metrics, pass timings) as JSON.
/// @throws InputError if the file cannot be written
void writeSummaryJson(const std::string& path, const Simulation& sim, const RunResult& result);

/// Writes the state as CSV with the header `i,x,y,z,vx,vy,vz`, one row per particle.
/// @throws InputError if the file cannot be written
void writeStateCsv(const std::string& path, const State& state);

}  // namespace clothlab
