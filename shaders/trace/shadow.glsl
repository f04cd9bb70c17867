// Soft self-shadowing towards the light (Tatarchuk 2006), traced from the hit point. The tutorials'
// version is "all black": it starts at the hit itself and never stops below the highest texel.
// Here the light ray rises from the hit in pxMinLayers..pxMaxLayers even steps up to the highest
// texel (nothing lies above it), and each sample's occluder is measured as the angle it rises
// above the ray, against the angular radius of the light (a penumbra in the manner of Quilez's
// soft shadows). A surface grazing the ray hides half the light; a flat surface under a light
// higher than its radius is fully lit.
//
// Q: the uv offset per unit of normalised height the light ray rises, s * l.xy / l.z for a light
// direction l (towards the light, tangent space, l.z > 0). softness in [0, 1]: 0 is a point light
// (hard shadows), 1 a light 0.5 rad (about 29 degrees) wide. Returns the visible fraction in [0, 1].
// Fetches: 1 + up to pxMinLayers..pxMaxLayers.

float pxSoftShadow(vec2 uv, float t, vec2 Q, float softness) {
    float top = pxHeightMax;
    if (1.0f - t >= top || pxScale <= 0.0f)
        return 1.0f;
    // Start on the surface itself: an approximate hit (steep, pom...) may lie a little below it,
    // and the surface just above would shadow it (acne). One fetch.
    float z0 = max(1.0f - t, pxHeight(uv));
    if (z0 >= top)
        return 1.0f;
    float run = length(Q) / pxScale; // uv travelled per unit of height, over s: tan of the polar angle
    float cosL = inversesqrt(1.0f + run * run);
    int samples = max(1, int(pxLerp(float(pxMaxLayers), float(pxMinLayers), cosL) + 0.5f));
    float dz = (top - z0) / float(samples);
    // The occluder's elevation above the ray is s gap / (rise sqrt(|Q|^2 + s^2)); sinL folds the
    // constant part so that the loop divides by nothing that can be zero.
    float sinOverRise = pxScale * inversesqrt(dot(Q, Q) + pxScale * pxScale);
    float radius = 0.25f * max(softness, 0.004f);
    float visible = 1.0f;
    for (int i = 1; i <= samples; ++i) {
        float rise = dz * float(i);
        float gap = pxHeight(uv + Q * rise) - (z0 + rise);
        float elevation = gap * sinOverRise / rise;
        visible = min(visible, clamp(0.5f - 0.5f * elevation / radius, 0.0f, 1.0f));
        if (visible <= 0.0f)
            return 0.0f;
    }
    return visible;
}
