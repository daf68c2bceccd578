// A triangle covering the viewport from gl_VertexID (3 vertices, no attributes; a VAO must be
// bound). vUv = (0, 0) bottom-left, (1, 1) top-right; vClip is the clip-space xy.
out vec2 vUv;
out vec2 vClip;

void main()
{
    vec2 p = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));
    vUv = p;
    vClip = p * 2.0 - 1.0;
    gl_Position = vec4(vClip, 1.0, 1.0); // at the far plane: the background sits behind everything
}
