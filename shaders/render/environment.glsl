// Image-based light's shared pieces (docs/lighting.md): the equirectangular mapping of
// core/include/parallax/light/Environment.h (u = atan2(x, z) / 2pi + 1/2, v = acos(y) / pi),
// the exposure and the filmic tone map. Read by the surface shader under an environment and by
// the background (background.frag.glsl).

vec2 pxEquirectUv(vec3 d) {
    vec3 n = normalize(d);
    return vec2(atan(n.x, n.z) / 6.28318531 + 0.5, acos(clamp(n.y, -1.0, 1.0)) / 3.14159265);
}

// Exposure in stops, then the ACES filmic curve as Narkowicz fitted it ("ACES Filmic Tone Mapping
// Curve", 2015): highlights roll off instead of clipping.
vec3 pxToneMap(vec3 c) {
    vec3 x = c * exp2(pxExposure);
    return clamp(x * (2.51 * x + 0.03) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0);
}
