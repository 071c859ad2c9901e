// The subcommands of the clothlab CLI; each lives in its own cmd_*.cpp.
#pragma once
#include <CLI/CLI.hpp>

namespace clothlab::cli {

/// Exit codes shared by all commands.
enum Exit { Ok = 0, BadInput = 1, NotImplementedYet = 2, Unstable = 3, Internal = 70 };

/// `run SCENE [--set k=v]... [--steps N | --seconds T] [--dump FILE.csv] [--out DIR]`
void addRunCommand(CLI::App& app, int& exit_code);

/// `study stability|precision|sag SCENE [options]` and `study extremes [options]`
void addStudyCommand(CLI::App& app, int& exit_code);

/// `hint N.M [LEVEL] [--exercises DIR]`: the hints of task N.M up to LEVEL (1 a question and its slide,
/// 2 one sub-step, 3 the formula); reads DIR/NN_name/hints.json, writes nothing
void addHintCommand(CLI::App& app, int& exit_code);

}  // namespace clothlab::cli
