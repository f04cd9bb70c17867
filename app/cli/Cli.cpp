#include "Cli.h"

#include "CommonOptions.h"
#include "Interrupt.h"
#include "parallax/Version.h"
#include "parallax/io/Inputs.h"
#include "parallax/io/OutputCheck.h"

#include <filesystem>
#include <iostream>
#include <new>
#include <vector>

namespace px::cli {

namespace {

// The options that name files a command writes; every other option whose value is an existing
// file is an input. (export's --out and shader's --dump-all are folders, checked by their own.)
bool namesOutputFile(const CLI::App& command, const std::string& option) {
    if (command.get_name() == "export")
        return false;
    return option == "--out" || option == "--plot" || option == "--csv";
}

// Refuses, before any work, an output that would overwrite an input or cannot be written; then
// records the command line's files: inputs (Inputs.h), and outputs that no file the run reads
// later (a material's maps, a mesh's buffers) may be.
Status checkFileOptions(const CLI::App& command) {
    std::vector<NamedPath> outputs, inputs;
    for (const CLI::Option* option : command.get_options()) {
        const std::string name = option->get_name();
        for (const std::string& value : option->results()) {
            std::error_code ec;
            if (namesOutputFile(command, name) && value != "-")
                outputs.push_back({name, value});
            else if (!value.empty() && std::filesystem::is_regular_file(value, ec))
                inputs.push_back({name, value});
        }
    }
    if (Status s = checkOutputs(outputs, inputs); !s)
        return s;
    for (const NamedPath& in : inputs) {
        if (Status s = noteInput(in.path, in.option); !s)
            return s;
    }
    for (const NamedPath& out : outputs) {
        if (Status s = planOutput(out.path, out.option); !s)
            return s;
    }
    return success();
}

} // namespace

int fail(const std::string& message) {
    std::cerr << "error: " << message << "\n";
    return 1;
}

std::vector<std::pair<CLI::App*, Action>> addCommands(CLI::App& app) {
    std::vector<std::pair<CLI::App*, Action>> entries;
    for (Action (*registrar)(CLI::App&) :
         {addSampleCommand, addTraceCommand, addShaderCommand, addRenderCommand, addExportCommand,
          addBenchCommand, addStabilityCommand, addBakeCommand, addRecommendCommand,
          addImportCommand}) {
        const std::size_t before = app.get_subcommands({}).size();
        Action action = registrar(app);
        entries.emplace_back(app.get_subcommands({}).at(before), std::move(action));
    }
    checkNumbers(app);
    return entries;
}

int run(int argc, char** argv) {
    CLI::App app{"Parallax Studio command line: bake, trace, render, benchmark and export "
                 "height-field materials without a display.",
                 "parallax-cli"};
    app.set_version_flag("--version", std::string("parallax-cli ") + kVersion);
    app.require_subcommand(1);

    installInterruptHandlers();
    const std::vector<std::pair<CLI::App*, Action>> entries = addCommands(app);

    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        if (e.get_exit_code() == 0)
            return app.exit(e); // --help, --version
        std::cerr << "error: " << e.what() << "\n"
                  << "Run 'parallax-cli --help' (or 'parallax-cli COMMAND --help') for usage.\n";
        return 2;
    }
    for (const auto& [command, action] : entries) {
        if (!command->parsed())
            continue;
        const InputSession session; // the run's record of what it reads
        if (Status s = checkFileOptions(*command); !s)
            return fail(s.error().message);
        try {
            return action();
        } catch (const std::bad_alloc&) {
            return fail("out of memory: the input is larger than this machine can hold (no "
                        "output was written)");
        }
    }
    return 2;
}

} // namespace px::cli
