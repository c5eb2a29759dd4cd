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

/// The same as JPEG (quality 1..100; alpha dropped).
bool write_jpg_rgba(const std::string& path, uint32_t width, uint32_t height, const uint8_t* pixels,
                    bool flip_y, int quality);

/// PNG or JPEG by the path's extension (.jpg/.jpeg: JPEG quality 90, anything else PNG).
bool write_image_rgba(const std::string& path, uint32_t width, uint32_t height, const uint8_t* pixels,
                      bool flip_y);

} // namespace pfs
