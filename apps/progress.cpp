#include "progress.hpp"

#include <algorithm>
#include <iostream>
#include <utility>
#include <unistd.h>

Progress::Progress(std::string program, const ExportOptions& options)
    : program_(std::move(program)),
      enabled_(options.show_progress && (options.progress || (!options.quiet && ::isatty(2) == 1))),
      terminal_(::isatty(2) == 1) {}

Progress::~Progress() {
    if (line_open_) std::cerr << "\r\033[K" << std::flush;  // leave the terminal as it was
}

void Progress::frame(int done, int total) {
    if (!enabled_) return;
    if (terminal_) {
        show("frame " + std::to_string(done) + "/" + std::to_string(total));
        return;
    }
    const int tenth = done * 10 / std::max(total, 1);  // a log gets a line per tenth
    if (tenth != last_tenth_) {
        last_tenth_ = tenth;
        show("frame " + std::to_string(done) + "/" + std::to_string(total));
    }
}

void Progress::stage(const std::string& what) {
    if (enabled_) show(what);
}

void Progress::pause() {
    if (line_open_) std::cerr << "\r\033[K" << std::flush;
    line_open_ = false;
}

void Progress::show(const std::string& text) {
    if (terminal_) {
        std::cerr << "\r\033[K" << program_ << ": " << text << std::flush;
        line_open_ = true;
    } else {
        std::cerr << program_ << ": " << text << '\n' << std::flush;
    }
}
