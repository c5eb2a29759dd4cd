// The one translation unit of the samples that compiles stb_image_write's implementation.
#include "image_write.h"

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

bool write_png_rgba(const std::string& path, uint32_t width, uint32_t height, const uint8_t* pixels,
                    bool flip_y) {
    const size_t row = size_t(width) * 4;
    if (!flip_y)
        return stbi_write_png(path.c_str(), int(width), int(height), 4, pixels, int(row)) != 0;
    // Flip into a scratch copy (stbi_flip_vertically_on_write is global state; avoid it).
    std::vector<uint8_t> flipped(row * height);
    for (uint32_t y = 0; y < height; ++y)
        std::memcpy(&flipped[size_t(y) * row], pixels + size_t(height - 1 - y) * row, row);
    return stbi_write_png(path.c_str(), int(width), int(height), 4, flipped.data(), int(row)) != 0;
}

} // namespace pfs
