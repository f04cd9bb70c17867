// Lighting models. Colours are linear; pxLightColor is the light's intensity (1 lights a white
// diffuse surface facing it to white), pxAmbient a constant fill scaled by ambient occlusion. Under
// an environment (PX_HAS_ENVIRONMENT) the fill is the environment's light instead, and the
// directional light stays as the sun, shadowed by the relief.

#define PX_PI 3.14159265f

#if defined(PX_HAS_ENVIRONMENT)
// E(n) / pi from nine spherical-harmonic coefficients (core/src/light/EnvironmentLighting.cpp).
vec3 pxIrradiance(vec3 n) {
    vec3 e = pxIrradianceSh[0] * 0.282095;
    e += pxIrradianceSh[1] * (0.488603 * n.y) + pxIrradianceSh[2] * (0.488603 * n.z) +
         pxIrradianceSh[3] * (0.488603 * n.x);
    e += pxIrradianceSh[4] * (1.092548 * n.x * n.y) + pxIrradianceSh[5] * (1.092548 * n.y * n.z) +
         pxIrradianceSh[6] * (0.315392 * (3.0 * n.z * n.z - 1.0)) +
         pxIrradianceSh[7] * (1.092548 * n.x * n.z) +
         pxIrradianceSh[8] * (0.546274 * (n.x * n.x - n.y * n.y));
    return max(e, vec3(0.0));
}

// The split sum (Karis 2013): diffuse from the irradiance; specular from the environment
// prefiltered at the roughness's level, times the table's scale and bias on F0.
vec3 pxEnvironmentLight(vec3 n, vec3 v, vec3 diffuseColor, vec3 F0, float roughness,
                        float occlusion) {
    float NdotV = max(dot(n, v), 1.0e-4);
    vec2 ab = textureLod(pxSplitSum, vec2(NdotV, roughness), 0.0).rg;
    vec3 r = reflect(-v, n);
    vec3 prefiltered = textureLod(pxEnvSpecular, pxEquirectUv(r), roughness * pxEnvMaxLevel).rgb;
    return (diffuseColor * pxIrradiance(n) + prefiltered * (F0 * ab.x + ab.y)) * occlusion;
}
#endif

// Blinn-Phong as in the tutorial shaders: ambient + Lambert + the normalised specular lobe
// (n + 2) / (2 pi) cos^n, here also weighted by N.L so that no highlight shows on the unlit side.
vec3 pxBlinnPhong(vec3 n, vec3 v, vec3 l, vec3 albedo, float occlusion, float lightVisible) {
    float NdotL = max(dot(n, l), 0.0);
    vec3 h = normalize(v + l);
    float NdotH = max(dot(n, h), 0.0);
    float lobe = (pxShininess + 2.0) * pow(NdotH, pxShininess) / (2.0 * PX_PI);
    vec3 direct = pxLightColor * (NdotL * lightVisible) * (albedo + vec3(pxSpecular * lobe));
#if defined(PX_HAS_ENVIRONMENT)
    // The lobe's width as a GGX roughness (Walter et al. 2007: alpha^2 = 2 / (n + 2)), the
    // specular weight as F0.
    float roughness = sqrt(sqrt(2.0 / (pxShininess + 2.0)));
    return pxEnvironmentLight(n, v, albedo, vec3(pxSpecular), roughness, occlusion) + direct;
#else
    return pxAmbient * occlusion * albedo + direct;
#endif
}

// Metallic-roughness as glTF 2.0 specifies it for engines: GGX distribution, Smith-Schlick
// visibility, Schlick Fresnel with F0 = 0.04 for dielectrics, Lambert diffuse for the rest.
vec3 pxMetallicRoughness(vec3 n, vec3 v, vec3 l, vec3 baseColor, float roughness, float metallic,
                         float occlusion, float lightVisible) {
    float NdotL = max(dot(n, l), 0.0);
    float NdotV = max(dot(n, v), 1.0e-4);
    vec3 h = normalize(v + l);
    float NdotH = max(dot(n, h), 0.0);
    float VdotH = max(dot(v, h), 0.0);
    float alpha = max(roughness * roughness, 1.0e-3);
    float alpha2 = alpha * alpha;
    float d = NdotH * NdotH * (alpha2 - 1.0) + 1.0;
    float D = alpha2 / (PX_PI * d * d);
    float k = (roughness + 1.0) * (roughness + 1.0) / 8.0;
    float G = NdotL / (NdotL * (1.0 - k) + k) * (NdotV / (NdotV * (1.0 - k) + k));
    vec3 F0 = mix(vec3(0.04), baseColor, metallic);
    vec3 F = F0 + (vec3(1.0) - F0) * pow(1.0 - VdotH, 5.0);
    vec3 specular = D * G * F / max(4.0 * NdotL * NdotV, 1.0e-4);
    vec3 diffuse = (vec3(1.0) - F) * (1.0 - metallic) * baseColor / PX_PI;
    vec3 direct = PX_PI * (diffuse + specular) * pxLightColor * (NdotL * lightVisible);
#if defined(PX_HAS_ENVIRONMENT)
    return pxEnvironmentLight(n, v, (1.0 - metallic) * baseColor, F0, roughness, occlusion) +
           direct;
#else
    return pxAmbient * occlusion * baseColor + direct;
#endif
}

// The framebuffer holds sRGB-encoded values (QOpenGLWidget's and the command line's alike).
vec3 pxLinearToSrgb(vec3 c) {
    vec3 x = clamp(c, 0.0, 1.0);
    return mix(x * 12.92, 1.055 * pow(x, vec3(1.0 / 2.4)) - 0.055, step(vec3(0.0031308), x));
}
