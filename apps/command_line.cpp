#include "command_line.hpp"

#include <exception>
#include <iostream>

std::optional<int> parse_command_line(CLI::App& app, int argc, char** argv) {
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& error) {
        if (error.get_exit_code() == 0) return app.exit(error);  // --help, --version
        std::cerr << app.get_name() << ": " << error.what() << " (see --help)\n";
        return 2;
    }
    return std::nullopt;
}

int run_exporter(CLI::App& app, const ExportOptions& options, int argc, char** argv,
                 const std::function<std::string()>& export_file) {
    if (const std::optional<int> exit_code = parse_command_line(app, argc, argv)) return *exit_code;
    try {
        const std::string report = export_file();
        std::ostream& out = options.output == "-" ? std::cerr : std::cout;
        if (!options.quiet && !(out << report << '\n' << std::flush)) return 1;  // e.g. a closed stdout
        return 0;
    } catch (const CLI::ParseError& error) {  // options that clash in a way only the run can see
        std::cerr << app.get_name() << ": " << error.what() << " (see --help)\n";
        return 2;
    } catch (const std::exception& error) {
        std::cerr << app.get_name() << ": " << error.what() << '\n';
        return 1;
    }
}
