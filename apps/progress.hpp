#pragma once

#include "export_options.hpp"

#include <string>

// Progress on stderr while frames are made: on a terminal, or everywhere with --progress.
class Progress {
public:
    Progress(std::string program, const ExportOptions& options);
    ~Progress();
    Progress(const Progress&) = delete;
    Progress& operator=(const Progress&) = delete;

    void frame(int done, int total);
    void stage(const std::string& what);
    // Clears the open progress line, so that what comes next starts on a clean line.
    void pause();

private:
    void show(const std::string& text);
    std::string program_;
    bool enabled_;
    bool terminal_;
    int last_tenth_ = -1;
    bool line_open_ = false;
};
