#pragma once

#include <string>
#include <utility>
#include <vector>
#include <CLI/CLI.hpp>

// Options that take only what they can use, each refusal a usage error in the option's terms.

// A decimal integer in [low, high]; anything else is a usage error that says so.
CLI::Option* add_integer_option(CLI::App& app, const std::string& name, int& value, int low, int high,
                                const std::string& help);
// Reads a decimal number into `value`: "" when it is finite, else why not, in the option's terms.
std::string read_finite(const std::string& given, double& value);
// A decimal number that is finite and within [low, high] (both ends open when `open_ends`); the
// error says in the option's terms what is wrong ("must be finite", "must be positive").
CLI::Validator finite_number(double low, double high, bool open_ends = false, const std::string& unit = "");
// Accepts only one of `names` (any case) and lower-cases it; the error lists the names.
CLI::Validator one_of(const std::vector<std::string>& names);

// A choice taken by name only: numbers and unknown names are usage errors that list the names.
template <typename Value>
CLI::Option* add_choice_option(CLI::App& app, const std::string& name, Value& value,
                               const std::vector<std::pair<std::string, Value>>& choices, const std::string& help,
                               const std::string& default_name) {
    std::vector<std::string> names;
    for (const auto& choice : choices) names.push_back(choice.first);
    const auto store = [&value, choices](const std::string& given) {
        for (const auto& [choice_name, choice_value] : choices) {
            if (choice_name == given) value = choice_value;
        }
    };
    return app.add_option_function<std::string>(name, store, help)
        ->transform(one_of(names))
        ->option_text(CLI::detail::join(names, "|") + " [" + default_name + "]");
}
