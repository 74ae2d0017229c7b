#pragma once

#include "export_options.hpp"

#include <functional>
#include <optional>
#include <string>
#include <CLI/CLI.hpp>

// Parses the command line; an exit code when the program should stop there: 0 after --help or
// --version, 2 after a usage error (reported in one line on stderr).
std::optional<int> parse_command_line(CLI::App& app, int argc, char** argv);

// Parses the command line and runs `export_file`, which returns the line to report: on stdout,
// or on stderr when the image itself goes to stdout, and not at all with --quiet. Usage errors
// exit 2, failures 1, each with one line on stderr.
int run_exporter(CLI::App& app, const ExportOptions& options, int argc, char** argv,
                 const std::function<std::string()>& export_file);
