// clothlab: the command-line front end (run scenes; further commands per layer).
#include <iostream>

#include "clothlab/core/input_error.h"
#include "clothlab/core/not_implemented.h"
#include "clothlab/core/stub_advice.h"
#include "commands.h"

int main(int argc, char** argv) {
    CLI::App app{"clothlab — cloth simulation lab course"};
    app.require_subcommand(1);
    int exit_code = clothlab::cli::Ok;
    clothlab::cli::addRunCommand(app, exit_code);
    clothlab::cli::addStudyCommand(app, exit_code);
    clothlab::cli::addHintCommand(app, exit_code);
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        return app.exit(e);
    } catch (const clothlab::InputError& e) {
        std::cerr << "error: " << e.what() << "\n";
        return clothlab::cli::BadInput;
    } catch (const clothlab::NotImplemented& e) {
        std::cerr << e.what() << clothlab::stubAdvice(e.what()) << "\n";
        return clothlab::cli::NotImplementedYet;
    } catch (const std::exception& e) {
        std::cerr << "error: internal: " << e.what() << "\n";
        return clothlab::cli::Internal;
    }
    return exit_code;
}
