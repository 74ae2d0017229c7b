#include "help_format.hpp"

#include <raster/version.hpp>

#include <memory>
#include <sstream>
#include <string>

namespace {

constexpr std::size_t kHelpWidth = 80;
constexpr std::size_t kOptionColumn = 30;

// Breaks lines longer than `width` at spaces; shorter lines, such as examples, stay as written.
std::string wrap(const std::string& text, std::size_t width) {
    std::string wrapped;
    std::istringstream lines(text);
    std::string line;
    while (std::getline(lines, line)) {
        if (!wrapped.empty()) wrapped += '\n';
        while (line.size() > width) {
            const std::size_t space = line.rfind(' ', width);
            if (space == std::string::npos || space == 0) break;
            wrapped += line.substr(0, space) + '\n';
            line.erase(0, space + 1);
        }
        wrapped += line;
    }
    return wrapped;
}

class WrappingFormatter : public CLI::Formatter {
public:
    std::string make_option_desc(const CLI::Option* option) const override {
        return wrap(option->get_description(), kHelpWidth - get_column_width());
    }
    std::string make_description(const CLI::App* app) const override {
        const std::string text = app->get_description();
        return text.empty() ? "" : wrap(text, kHelpWidth) + "\n\n";
    }
    std::string make_footer(const CLI::App* app) const override {
        const std::string text = app->get_footer();
        return text.empty() ? "" : wrap(text, kHelpWidth) + "\n";
    }
};

}  // namespace

void configure_app(CLI::App& app) {
    auto formatter = std::make_shared<WrappingFormatter>();
    formatter->column_width(kOptionColumn);
    app.formatter(formatter);
    app.set_version_flag("--version", app.get_name() + " " + raster::kVersion + " (raster)",
                         "Print the program's name and version, then exit");
    app.set_help_flag("-h,--help", "Print this help, then exit");
}
