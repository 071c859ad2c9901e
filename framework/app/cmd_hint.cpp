// `clothlab hint N.M`: progressive hints for task N.M, one level more per call.
//
// exercises/NN_name/hints.json holds three levels per task: (1) the physical requirement and where
// it is on the slides, (2) the formula, (3) a pseudocode outline. The levels taken are recorded in
// exercises/NN_name/hints_taken.json ({"N.M": level}); that file travels with the submission and
// the grader reports it beside the points (what it means is the instructor's call).
#include <fstream>
#include <iostream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "clothlab/core/input_error.h"
#include "commands.h"

namespace clothlab::cli {

namespace fs = std::filesystem;
using json = nlohmann::ordered_json;

namespace {

json readJson(const fs::path& file) {
    std::ifstream in(file);
    if (!in) throw InputError(file.string(), "(file)", "cannot read it");
    json j = json::parse(in, nullptr, false);
    if (j.is_discarded() || !j.is_object()) throw InputError(file.string(), "(JSON syntax)", "not a JSON object");
    return j;
}

void showHint(const std::string& task, const fs::path& exercises, bool peek) {
    const auto digit = [&](size_t i, char lo) { return i < task.size() && task[i] >= lo && task[i] <= '9'; };
    const bool wellFormed =  // N.M: N in 1-9, M in 1-99
        (task.size() == 3 || (task.size() == 4 && digit(3, '0'))) && digit(0, '1') && task[1] == '.' && digit(2, '1');
    if (!wellFormed) throw InputError("command line", "hint " + task, "a task number looks like 4.2 (stage 4, task 2)");
    const std::string nn = "0" + task.substr(0, 1);
    fs::path stage;
    if (fs::is_directory(exercises))
        for (const auto& e : fs::directory_iterator(exercises))
            if (e.is_directory() && e.path().filename().string().rfind(nn + "_", 0) == 0) stage = e.path();
    if (stage.empty()) throw InputError(exercises.string(), "(folder)", "no stage " + nn + "_* for task " + task);
    const fs::path file = stage / "hints.json", taken_file = stage / "hints_taken.json";
    const json hints = readJson(file);
    if (!hints.contains(task)) {
        std::string tasks;
        for (auto it = hints.begin(); it != hints.end(); ++it) tasks += (tasks.empty() ? "" : ", ") + it.key();
        throw InputError(file.string(), task, "no such task (tasks: " + tasks + ")");
    }
    const json& levels = hints[task];
    if (!levels.is_array() || levels.empty())
        throw InputError(file.string(), task, "must be a list of hint levels");
    for (const auto& l : levels)
        if (!l.is_string()) throw InputError(file.string(), task, "every hint level must be a string");
    json taken = fs::exists(taken_file) ? readJson(taken_file) : json::object();
    const int before = taken.contains(task) && taken[task].is_number_integer() ? taken[task].get<int>() : 0;
    const int n = static_cast<int>(levels.size());
    const int shown = std::min(n, peek ? std::max(before, 0) : before + 1);
    if (shown == 0) {
        std::cout << "task " << task << ": no hint taken yet (./lab hint " << task << " shows level 1 of " << n << ")\n";
        return;
    }
    for (int i = 0; i < shown; ++i) std::cout << "hint " << task << ", level " << i + 1 << " of " << n << ":\n  " << levels[i].get<std::string>() << "\n\n";
    if (!peek && shown > before) {
        taken[task] = shown;
        std::ofstream out(taken_file);
        out << taken.dump(2) << "\n";
        if (!out) throw InputError(taken_file.string(), "(file)", "cannot write it");
    }
    std::cout << (shown == n ? "that was the last level." : "./lab hint " + task + " again shows the next level.")
              << " Hints taken are recorded in " << taken_file.string() << " and shown with your grade.\n";
}

}  // namespace

void addHintCommand(CLI::App& app, int& exit_code) {
    auto* cmd = app.add_subcommand("hint", "Progressive hints for a task: one level more per call");
    auto task = std::make_shared<std::string>();
    auto exercises = std::make_shared<std::string>("exercises");
    auto peek = std::make_shared<bool>(false);
    cmd->add_option("task", *task, "Task number, e.g. 4.2")->required();
    cmd->add_option("--exercises", *exercises, "The folder with the stages (default: exercises)");
    cmd->add_flag("--shown", *peek, "Show the levels taken so far, take no new one");
    cmd->callback([=, &exit_code] {
        showHint(*task, *exercises, *peek);
        exit_code = Ok;
    });
}

}  // namespace clothlab::cli
