// PNG output for the samples (stb_image_write behind a small function).
#pragma once

#include <cstdint>
#include <string>

namespace pfs {

/// Writes an 8-bit RGBA image of width x height pixels, rows tightly packed. GL's
/// glReadPixels returns the bottom row first: pass flip_y = true to write it upright.
/// Returns false on failure (errno tells why).
bool write_png_rgba(const std::string& path, uint32_t width, uint32_t height, const uint8_t* pixels,
                    bool flip_y);

} // namespace pfs
