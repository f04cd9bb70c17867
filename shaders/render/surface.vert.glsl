// Meshes: world-space position, normal, tiled uv and, unless the fragment shader derives its frame
// from screen-space derivatives, the tangent frame T = dP/du, B = dP/dv (docs/conventions.md §2) at
// full length: the lengths say how many world units one uv unit spans, which sets the depth scale.

layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in vec2 aUv;
layout(location = 3) in vec3 aTangent;
layout(location = 4) in vec3 aBitangent;

out vec3 vPosition;
out vec3 vNormal;
out vec2 vUv;
out vec3 vTangent;
out vec3 vBitangent;

// The generator defines PX_FRAGMENT_READS_<INPUT> for each input the fragment stage keeps: an
// output nobody reads is not written, so nothing it alone needs is declared.
void main() {
    vec4 world = pxModel * vec4(aPosition, 1.0);
#if defined(PX_FRAGMENT_READS_VPOSITION)
    vPosition = world.xyz;
#endif
#if defined(PX_FRAGMENT_READS_VNORMAL)
    vNormal = pxNormalMatrix * aNormal;
#endif
#if defined(PX_FRAGMENT_READS_VUV)
    vUv = aUv * pxTiling;
#endif
    // Tangents follow the surface (the model matrix, not the normal matrix); tiling packs more uv
    // into the same length.
#if defined(PX_FRAGMENT_READS_VTANGENT)
    vTangent = mat3(pxModel) * aTangent / pxTiling.x;
#endif
#if defined(PX_FRAGMENT_READS_VBITANGENT)
    vBitangent = mat3(pxModel) * aBitangent / pxTiling.y;
#endif
    gl_Position = pxViewProjection * world;
}
