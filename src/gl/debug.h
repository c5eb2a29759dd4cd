// KHR_debug (core in GL 4.3) markers for RenderDoc, Nsight and the engine's own debug tools:
// every GL object pflip makes carries the label "pflip/<name>", and every pass it dispatches
// or draws runs inside a debug group "pflip/<pass name>". Both are used only where the engine's
// loader supplied the entry points (src/gl/entry_points_optional.inc); otherwise they cost one
// pointer test. Groups are always popped before a call returns, so the engine's debug group
// stack is as it was; nothing else of the engine's debug state (callback, message control,
// GL_DEBUG_OUTPUT) is touched.
#pragma once
#include <string>

#include "gl/gl.h"

namespace pf::gl {

// The entry points of labels and groups are all there.
inline bool has_debug_markers(const Api& gl) { return gl.ObjectLabel && gl.PushDebugGroup && gl.PopDebugGroup; }

// Labels object `name` of kind `identifier` (GL_BUFFER, GL_PROGRAM, GL_TEXTURE, ...) "pflip/<label>".
// The object must exist (a texture, framebuffer or vertex array only once it was first bound).
inline void label_object(const Api& gl, GLenum identifier, GLuint name, const char* label) {
    if (!gl.ObjectLabel || !name || !label) return;
    const std::string text = std::string("pflip/") + label;
    gl.ObjectLabel(identifier, name, GLsizei(text.size()), text.c_str());
}

// Pushes the debug group `text` (already "pflip/..."), popped at scope exit.
class DebugGroup {
public:
    DebugGroup(const Api& gl, const char* text) : gl_(gl), on_(gl.PushDebugGroup && gl.PopDebugGroup) {
        if (on_) gl_.PushDebugGroup(GL_DEBUG_SOURCE_APPLICATION, 0, -1, text);
    }
    ~DebugGroup() {
        if (on_) gl_.PopDebugGroup();
    }
    DebugGroup(const DebugGroup&) = delete;
    DebugGroup& operator=(const DebugGroup&) = delete;

private:
    const Api& gl_;
    bool on_;
};

}  // namespace pf::gl
