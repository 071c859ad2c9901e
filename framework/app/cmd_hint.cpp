// `clothlab hint N.M [LEVEL]`: the hints of task N.M up to LEVEL (default 1).
//
// exercises/NN_name/hints.json holds three levels per task: (1) a guiding question that names the
// slide to look at, (2) one sub-step, (3) the formula. Hints are free help: the command only reads
// hints.json and prints; it writes no file and keeps no record.
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

// What each of the three levels is (exercises/NN_name/hints.json keeps this order).
const char* const kLevelMeaning[] = {"a question and the slide to look at", "one sub-step", "the formula"};

void showHint(const std::string& task, const std::string& level_arg, const fs::path& exercises) {
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
    const fs::path file = stage / "hints.json";
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
    const int n = static_cast<int>(levels.size());
    const int level = level_arg.size() == 1 && level_arg[0] >= '1' && level_arg[0] <= '9' ? level_arg[0] - '0' : 0;
    if (level < 1 || level > n)
        throw InputError("command line", "hint " + task + " " + level_arg, "the level is 1 to " + std::to_string(n));
    const auto meaning = [&](int i) { return n == 3 ? std::string(" (") + kLevelMeaning[i] + ")" : std::string(); };
    for (int i = 0; i < level; ++i)
        std::cout << "hint " << task << ", level " << i + 1 << " of " << n << meaning(i) << ":\n  "
                  << levels[i].get<std::string>() << "\n\n";
    if (level < n)
        std::cout << "more: ./lab hint " << task << " " << level + 1 << meaning(level) << "\n";
}

}  // namespace

void addHintCommand(CLI::App& app, int& exit_code) {
    auto* cmd = app.add_subcommand(
        "hint", "Hints for a task, levels 1 to LEVEL: 1 a question and its slide, 2 one sub-step, 3 the formula");
    auto task = std::make_shared<std::string>();
    auto level = std::make_shared<std::string>("1");
    auto exercises = std::make_shared<std::string>("exercises");
    cmd->add_option("task", *task, "Task number, e.g. 4.2")->required();
    cmd->add_option("level", *level, "Show levels 1 to LEVEL (default 1)");
    cmd->add_option("--exercises", *exercises, "The folder with the stages (default: exercises)");
    cmd->callback([=, &exit_code] {
        showHint(*task, *level, *exercises);
        exit_code = Ok;
    });
}

}  // namespace clothlab::cli
