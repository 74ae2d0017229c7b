#pragma once

#include <cstddef>
#include <string_view>

// OBJ text as lines and statements, the same way for counting a byte range and for reading it.
namespace raster::detail {

// The lines of a text in order, each without its end: "\n", "\r\n" or a lone "\r" (as for_each_line splits them).
class TextLines {
public:
    explicit TextLines(std::string_view text) : text_(text) {}

    // The next line; false after the last.
    bool next(std::string_view& line) {
        if (at_ >= text_.size()) return false;
        const char* const begin = text_.data() + at_;
        const char* const end = text_.data() + text_.size();
        const char* p = begin;
        while (p != end && *p != '\n' && *p != '\r') ++p;
        line = {begin, static_cast<std::size_t>(p - begin)};
        const bool crlf = p != end && *p == '\r' && p + 1 != end && p[1] == '\n';
        at_ = p == end ? text_.size() : static_cast<std::size_t>(p - text_.data()) + (crlf ? 2 : 1);
        return true;
    }

private:
    std::string_view text_;
    std::size_t at_ = 0;
};

// The statements raster reads; every other keyword (g, o, s, vp, curves ...) is passed over.
enum class ObjStatement { other, position, uv, normal, face, point, line, library, material };

// The statement a line makes: its first word after any spaces and tabs, which a space or a tab
// must follow ("v" alone at a line's end is no vertex; "usemtl" is); `rest` receives what follows the keyword.
inline ObjStatement statement_of(std::string_view line, std::string_view& rest) {
    std::size_t start = 0;
    while (start < line.size() && (line[start] == ' ' || line[start] == '\t')) ++start;
    std::size_t end = start;
    while (end < line.size() && line[end] != ' ' && line[end] != '\t') ++end;
    if (end == line.size()) {  // a bare usemtl is the default material, as tinyobjloader took it
        rest = {};
        return line.substr(start) == "usemtl" ? ObjStatement::material : ObjStatement::other;
    }
    const std::string_view keyword = line.substr(start, end - start);
    rest = line.substr(end);
    switch (keyword.size()) {
    case 1:
        return keyword[0] == 'v'   ? ObjStatement::position
               : keyword[0] == 'f' ? ObjStatement::face
               : keyword[0] == 'p' ? ObjStatement::point
               : keyword[0] == 'l' ? ObjStatement::line
                                   : ObjStatement::other;
    case 2: return keyword == "vt" ? ObjStatement::uv : keyword == "vn" ? ObjStatement::normal : ObjStatement::other;
    case 6:
        return keyword == "mtllib"   ? ObjStatement::library
               : keyword == "usemtl" ? ObjStatement::material
                                     : ObjStatement::other;
    default: return ObjStatement::other;
    }
}

// The space- or tab-separated words of a statement, one at a time.
class Words {
public:
    explicit Words(std::string_view text) : text_(text) {}

    // The next word, or an empty one after the last.
    std::string_view next() {
        while (at_ < text_.size() && (text_[at_] == ' ' || text_[at_] == '\t')) ++at_;
        const std::size_t start = at_;
        while (at_ < text_.size() && text_[at_] != ' ' && text_[at_] != '\t') ++at_;
        return text_.substr(start, at_ - start);
    }

private:
    std::string_view text_;
    std::size_t at_ = 0;
};

}  // namespace raster::detail
