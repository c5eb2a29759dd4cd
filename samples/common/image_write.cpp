// The one translation unit of the samples that compiles stb_image_write's implementation.
#include "image_write.h"

#include <cctype>
#include <cstring>
#include <vector>

#define STB_IMAGE_WRITE_IMPLEMENTATION
#if defined(__GNUC__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wunused-parameter"
#pragma GCC diagnostic ignored "-Wsign-compare"
#endif
#include <stb_image_write.h>
#if defined(__GNUC__)
#pragma GCC diagnostic pop
#endif

namespace pfs {

namespace {
// Flip into a scratch copy (stbi_flip_vertically_on_write is global state; avoid it).
const uint8_t* maybe_flip(uint32_t width, uint32_t height, const uint8_t* pixels, bool flip_y,
                          std::vector<uint8_t>& scratch) {
    if (!flip_y) return pixels;
    const size_t row = size_t(width) * 4;
    scratch.resize(row * height);
    for (uint32_t y = 0; y < height; ++y)
        std::memcpy(&scratch[size_t(y) * row], pixels + size_t(height - 1 - y) * row, row);
    return scratch.data();
}
} // namespace

bool write_png_rgba(const std::string& path, uint32_t width, uint32_t height, const uint8_t* pixels,
                    bool flip_y) {
    std::vector<uint8_t> scratch;
    const uint8_t* p = maybe_flip(width, height, pixels, flip_y, scratch);
    return stbi_write_png(path.c_str(), int(width), int(height), 4, p, int(size_t(width) * 4)) != 0;
}

bool write_jpg_rgba(const std::string& path, uint32_t width, uint32_t height, const uint8_t* pixels,
                    bool flip_y, int quality) {
    std::vector<uint8_t> scratch;
    const uint8_t* p = maybe_flip(width, height, pixels, flip_y, scratch);
    // Drop alpha (stb writes RGBA JPEGs as RGB anyway, but be explicit).
    std::vector<uint8_t> rgb(size_t(width) * height * 3);
    for (size_t i = 0, n = size_t(width) * height; i < n; ++i)
        for (int c = 0; c < 3; ++c) rgb[i * 3 + size_t(c)] = p[i * 4 + size_t(c)];
    return stbi_write_jpg(path.c_str(), int(width), int(height), 3, rgb.data(), quality) != 0;
}

bool write_image_rgba(const std::string& path, uint32_t width, uint32_t height, const uint8_t* pixels,
                      bool flip_y) {
    auto ends_with = [&](const char* ext) {
        const size_t n = std::strlen(ext);
        if (path.size() < n) return false;
        for (size_t i = 0; i < n; ++i)
            if (std::tolower(static_cast<unsigned char>(path[path.size() - n + i])) != ext[i]) return false;
        return true;
    };
    if (ends_with(".jpg") || ends_with(".jpeg")) return write_jpg_rgba(path, width, height, pixels, flip_y, 90);
    return write_png_rgba(path, width, height, pixels, flip_y);
}

} // namespace pfs
