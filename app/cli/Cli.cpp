#include "Cli.h"

#include "parallax/Version.h"

#include <iostream>
#include <vector>

namespace px::cli {

int fail(const std::string& message) {
    std::cerr << "error: " << message << "\n";
    return 1;
}

int run(int argc, char** argv) {
    CLI::App app{"Parallax Studio command line: bake, trace, render, benchmark and export "
                 "height-field materials without a display.",
                 "parallax-cli"};
    app.set_version_flag("--version", std::string("parallax-cli ") + kVersion);
    app.require_subcommand(1);

    struct Entry {
        CLI::App* command;
        Action action;
    };
    std::vector<Entry> entries;
    auto add = [&](Action (*registrar)(CLI::App&)) {
        const std::size_t before = app.get_subcommands({}).size();
        Action action = registrar(app);
        entries.push_back({app.get_subcommands({}).at(before), std::move(action)});
    };
    add(addSampleCommand);
    add(addTraceCommand);
    add(addShaderCommand);
    add(addRenderCommand);
    add(addExportCommand);
    add(addBenchCommand);
    add(addStabilityCommand);
    add(addBakeCommand);
    add(addRecommendCommand);

    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        if (e.get_exit_code() == 0)
            return app.exit(e); // --help, --version
        std::cerr << "error: " << e.what() << "\n"
                  << "Run 'parallax-cli --help' (or 'parallax-cli COMMAND --help') for usage.\n";
        return 2;
    }
    for (const Entry& entry : entries) {
        if (entry.command->parsed())
            return entry.action();
    }
    return 2;
}

} // namespace px::cli
