#pragma once

#include <raster/io/input_file.hpp>

#include <array>
#include <cstdint>
#include <span>
#include <streambuf>

// A std::istream source over an InputFile, for parsers that take streams (tinyobjloader). A UTF-8
// byte order mark at the start is skipped, as the survey skips it: both readings see one text.
namespace raster::detail {

class InputStreamBuf final : public std::streambuf {
public:
    explicit InputStreamBuf(InputFile& file) : file_(file) { file_.rewind(); }

protected:
    int_type underflow() override {
        std::size_t got = file_.read_some(buffer_);
        std::size_t skip = 0;
        if (at_start_) {
            while (got < 3) {  // a file read a byte at a time still shows its mark whole
                const std::size_t more = file_.read_some(std::span(buffer_).subspan(got));
                if (more == 0) break;
                got += more;
            }
            if (got >= 3 && buffer_[0] == 0xEF && buffer_[1] == 0xBB && buffer_[2] == 0xBF) skip = 3;
            at_start_ = false;
        }
        if (got == skip) return traits_type::eof();
        char* start = reinterpret_cast<char*>(buffer_.data());
        setg(start, start + skip, start + got);
        return traits_type::to_int_type(start[skip]);
    }
    // Only a return to the start is needed: the survey and the parse each read from there.
    pos_type seekoff(off_type offset, std::ios_base::seekdir direction, std::ios_base::openmode) override {
        if (offset != 0 || direction != std::ios_base::beg) return pos_type(off_type(-1));
        file_.rewind();
        at_start_ = true;
        setg(nullptr, nullptr, nullptr);
        return pos_type(0);
    }
    pos_type seekpos(pos_type position, std::ios_base::openmode which) override {
        return seekoff(off_type(position), std::ios_base::beg, which);
    }

private:
    InputFile& file_;
    bool at_start_ = true;
    std::array<std::uint8_t, std::size_t{1} << 16> buffer_{};
};

}  // namespace raster::detail
