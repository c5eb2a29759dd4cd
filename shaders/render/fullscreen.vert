// One triangle covering the viewport (vertices from gl_VertexID, no attributes). z = 0.5 w
// lies inside the clip range of both glClipControl depth modes.
void main() {
    vec2 p = vec2(float((gl_VertexID & 1) * 4 - 1), float((gl_VertexID >> 1) * 4 - 1));
    gl_Position = vec4(p, 0.5, 1.0);
}
