// The wireframe overlay's vertex stage (View > Wireframe, docs/rendering.md "Inspection views"):
// positions only, transformed as the surface pass transforms them (render/GpuMesh's attribute 0).
layout(location = 0) in vec3 aPosition;

uniform mat4 uModel;
uniform mat4 uViewProjection;

void main()
{
    gl_Position = uViewProjection * (uModel * vec4(aPosition, 1.0));
}
