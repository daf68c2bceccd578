// The surface pass's vertex stage. Attribute locations match render/GpuMesh (core/mesh/Mesh.h's
// Vertex: position, normal, tangent, uv, color, uv1). Without HAS_TANGENT_FRAME (a normal map of
// the base or the coat: render/ShaderVariant surfaceDefines) no tangent is read,
// without HAS_TEXCOORD_1 no second UV, without HAS_VERTEX_COLOR no colour.
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
#ifdef HAS_TANGENT_FRAME
layout(location = 2) in vec4 aTangent; // xyz along dP/du, w = handedness (glTF 2.0)
out vec4 vTangent;
#endif
layout(location = 3) in vec2 aUv;
#ifdef HAS_TEXCOORD_1
layout(location = 5) in vec2 aUv1; // glTF TEXCOORD_1 (core/mesh/Mesh.h Vertex::uv1)
out vec2 vUv1;
#endif
#ifdef HAS_VERTEX_COLOR
layout(location = 4) in vec4 aColor; // glTF COLOR_0, linear RGBA (core/mesh/Mesh.h Vertex::color)
out vec4 vColor;
#endif

uniform mat4 uModel;
uniform mat3 uNormalMatrix; // inverse transpose of uModel's upper 3x3
uniform mat4 uViewProjection;

out vec3 vWorldPosition;
out vec3 vNormal;
out vec2 vUv;

void main()
{
    vec4 world = uModel * vec4(aPosition, 1.0);
    vWorldPosition = world.xyz;
    vNormal = uNormalMatrix * aNormal;
    vUv = aUv;
#ifdef HAS_TEXCOORD_1
    vUv1 = aUv1;
#endif
#ifdef HAS_VERTEX_COLOR
    vColor = aColor;
#endif
#ifdef HAS_TANGENT_FRAME
    vTangent = vec4(mat3(uModel) * aTangent.xyz, aTangent.w);
#endif
    gl_Position = uViewProjection * world;
}
