// A triangle that covers the viewport, from gl_VertexID alone (draw 3 vertices, no attributes;
// core profile still needs a vertex array object bound). vUv is (0,0) at the bottom-left
// corner of the viewport, (1,1) at the top-right: for a render into a texture level it is the
// texel's texture coordinate (s, t).
out vec2 vUv;

void main()
{
    vec2 p = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));
    vUv = p;
    gl_Position = vec4(p * 2.0 - 1.0, 0.0, 1.0);
}
