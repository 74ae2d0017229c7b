#pragma once

#include <raster/input_file.hpp>

#include <array>
#include <cstdint>
#include <streambuf>

// A std::istream source over an InputFile, for parsers that take streams (tinyobjloader).
namespace raster::detail {

class InputStreamBuf final : public std::streambuf {
public:
    explicit InputStreamBuf(InputFile& file) : file_(file) { file_.rewind(); }

protected:
    int_type underflow() override {
        const std::size_t got = file_.read_some(buffer_);
        if (got == 0) return traits_type::eof();
        char* start = reinterpret_cast<char*>(buffer_.data());
        setg(start, start, start + got);
        return traits_type::to_int_type(*start);
    }
    // Only a return to the start is needed: the survey and the parse each read from there.
    pos_type seekoff(off_type offset, std::ios_base::seekdir direction, std::ios_base::openmode) override {
        if (offset != 0 || direction != std::ios_base::beg) return pos_type(off_type(-1));
        file_.rewind();
        setg(nullptr, nullptr, nullptr);
        return pos_type(0);
    }
    pos_type seekpos(pos_type position, std::ios_base::openmode which) override {
        return seekoff(off_type(position), std::ios_base::beg, which);
    }

private:
    InputFile& file_;
    std::array<std::uint8_t, std::size_t{1} << 16> buffer_{};
};

}  // namespace raster::detail
