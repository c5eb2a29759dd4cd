// The screen-space liquid's own textures and framebuffers, of the viewport's size (the thickness
// of half of it in each axis, the scene depth tiles of an eighth):
// (re)allocated when the viewport size changes (the scene depth copy once a call gives a scene
// depth), never touching an engine object.
#pragma once
#include <array>
#include <cstdint>

#include "common/render_slots.h"
#include "gl/gl.h"
#include "gl/objects.h"

namespace pf {

class SsfTargets {
public:
    enum Texture {
        scene_color,   // RGBA16F copy of the engine's scene colour (refraction source)
        scene_depth,   // R32F eye depth of the engine's scene depth
        scene_depth_tiles,  // R32F its nearest eye depth per PF_RENDER_TILE tile
        thickness,     // R32F additive thickness, half resolution
        raw_depth,     // R32F nearest sphere eye depth (PF_NO_LIQUID elsewhere)
        depth_buffer,  // DEPTH_COMPONENT32F: keeps the nearest sphere in the depth pass
        smooth_a,      // R32F ping-pong targets of the smoothing passes
        smooth_b,
        shaded_color,  // RGBA16F liquid colour, alpha 1 where there is liquid
        shaded_depth,  // R32F liquid window depth, engine convention
        splat_depth_bits,      // R32UI compute splat: nearest eye depth as float bits
        splat_thickness_bits,  // R32UI compute splat: thickness in fixed point, half resolution
        texture_count
    };
    enum Framebuffer {
        thickness_fb,
        depth_fb,    // raw_depth + depth_buffer
        smooth_a_fb,
        smooth_b_fb,
        shade_fb,    // shaded_color + shaded_depth
        framebuffer_count
    };

    explicit SsfTargets(const gl::Api& gl);

    // Makes every texture width x height (the thickness half, the scene depth tiles a tile of it),
    // and the scene depth copy and its tiles if `scene_depth` (an existing copy is kept). Binds
    // textures on the active unit and framebuffers on GL_DRAW_FRAMEBUFFER: call under a
    // RenderStateGuard.
    void ensure(int width, int height, bool scene_depth);

    GLuint texture(Texture t) const { return textures_[t].id(); }
    // Size of the half-resolution textures for `size` pixels.
    static int half(int size) { return (size + 1) / 2; }
    // Pixels per texel along each axis of texture t.
    static int divisor(Texture t) {
        return t == thickness || t == splat_thickness_bits ? 2 : t == scene_depth_tiles ? PF_RENDER_TILE : 1;
    }
    // Texels along an axis of `size` pixels at `divisor` pixels per texel.
    static int reduced(int size, int divisor) { return (size + divisor - 1) / divisor; }
    GLuint framebuffer(Framebuffer f) const { return framebuffers_[f].id(); }
    // GPU memory of the textures made so far, bytes.
    uint64_t bytes() const;

private:
    void allocate(Texture t, GLenum format);
    void attach(Framebuffer f, GLenum attachment, Texture t);
    void attach_all();

    const gl::Api& gl_;
    int width_ = 0, height_ = 0;
    std::array<gl::Object, texture_count> textures_;
    std::array<gl::Object, framebuffer_count> framebuffers_;
};

}  // namespace pf
