#include "io/named_path.hpp"

#include <algorithm>
#include <cctype>
#include <string>
#include <system_error>

namespace raster::detail {

namespace fs = std::filesystem;

namespace {

// Entries looked at in one directory before giving up: a huge folder is not scanned whole.
constexpr int kMaxEntriesScanned = 100000;

bool same_ignoring_case(std::string_view a, std::string_view b) {
    return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
               return std::tolower(static_cast<unsigned char>(x)) == std::tolower(static_cast<unsigned char>(y));
           });
}

bool present(const fs::path& path) {
    std::error_code error;
    return fs::exists(path, error);
}

bool inside(const fs::path& path, const fs::path& root) {
    std::error_code error;
    const fs::path relative = fs::weakly_canonical(fs::absolute(path, error), error).lexically_relative(root);
    return !error && !relative.empty() && *relative.begin() != "..";
}

// The one entry of `folder` named `part` but for letter case; empty if none or several.
fs::path entry_ignoring_case(const fs::path& folder, const std::string& part) {
    std::error_code error;
    fs::path found;
    int scanned = 0;
    for (fs::directory_iterator it(folder.empty() ? fs::path(".") : folder, error), end; !error && it != end;
         it.increment(error)) {
        if (++scanned > kMaxEntriesScanned) return {};
        const std::string name = it->path().filename().string();
        if (!same_ignoring_case(name, part)) continue;
        if (!found.empty()) return {};  // "Wood.png" and "wood.PNG": which was meant is unknown
        found = folder / name;
    }
    return found;
}

}  // namespace

fs::path resolve_named_path(const fs::path& directory, std::string_view written, const fs::path& confine) {
    const fs::path as_written = directory / fs::path(std::string(written));
    if (present(as_written)) return as_written;
    std::string text(written);
    if (text.size() >= 2 && (text.front() == '"' || text.front() == '\'') && text.back() == text.front())
        text = text.substr(1, text.size() - 2);
    std::replace(text.begin(), text.end(), '\\', '/');
    const fs::path relative(text);
    if (relative.empty()) return as_written;
    fs::path current = relative.is_absolute() ? relative.root_path() : directory;
    for (const fs::path& part : relative.relative_path()) {
        const std::string name = part.string();
        if (name.empty() || name == ".") continue;
        fs::path next = current / part;
        if (!present(next) && name != "..") {
            if (!confine.empty() && !inside(current, confine)) return as_written;  // no listing outside the confinement
            next = entry_ignoring_case(current, name);
            if (next.empty()) return as_written;
        }
        current = next;
    }
    return current;
}

}  // namespace raster::detail
