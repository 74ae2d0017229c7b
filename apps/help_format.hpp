#pragma once

#include <CLI/CLI.hpp>

// A CLI11 app whose help is wrapped to 80 columns and whose --version names the program.
void configure_app(CLI::App& app);
