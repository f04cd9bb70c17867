// Shading a mesh with the variant's technique. The frame T = dP/du, B = dP/dv, N
// (docs/conventions.md §2) comes from the vertex data or from screen-space derivatives; the view
// ray is taken into the tangent space (uv, uv, depth in uv units) to get P = s d.xy / (-d.z); the
// shared kernel finds the hit; normal, material and light are then read at the hit. The generator
// defines PX_HAS_TANGENT_FRAME and PX_HAS_TEXTURE_COORDINATES when the variant needs them.

in vec3 vPosition;
in vec3 vNormal;
in vec2 vUv;
in vec3 vTangent;
in vec3 vBitangent;

layout(location = 0) out vec4 pxFragColor;

// cos 89 degrees: the surface output's steepest view (see its end).
#define PX_STEEPEST_MEASURED_COS 0.0174524064

vec3 pxSafeNormalize(vec3 v, vec3 fallback) {
    float len2 = dot(v, v);
    return len2 > 1.0e-30 ? v * inversesqrt(len2) : fallback;
}

void main() {
#if defined(PX_HAS_SURFACE_OUTPUT) && !defined(PX_HAS_PARALLAX)
    pxFragColor = vec4(vUv, 0.0, 0.0); // nothing is traced: the hit is the surface point
#else
    vec3 N = pxSafeNormalize(vNormal, vec3(0.0, 0.0, 1.0));
    if (!gl_FrontFacing)
        N = -N;
    vec3 toCamera = pxCameraPos - vPosition;
#if defined(PX_HAS_TANGENT_FRAME)
#if defined(PX_HAS_DERIVATIVE_TBN)
    // The frame from screen-space derivatives, for meshes without tangents: solve
    // [dp/dx dp/dy] = [T B] [duv/dx duv/dy] for T and B, then project them onto the tangent plane
    // of the interpolated normal.
    vec3 dpdx = dFdx(vPosition);
    vec3 dpdy = dFdy(vPosition);
    vec2 duvdx = dFdx(vUv);
    vec2 duvdy = dFdy(vUv);
    float det = duvdx.x * duvdy.y - duvdy.x * duvdx.y;
    float invDet = det != 0.0 ? 1.0 / det : 0.0;
    vec3 T = (dpdx * duvdy.y - dpdy * duvdx.y) * invDet;
    vec3 B = (dpdy * duvdx.x - dpdx * duvdy.x) * invDet;
    T -= N * dot(N, T);
    B -= N * dot(N, B);
#else
    vec3 T = vTangent;
    vec3 B = vBitangent;
#endif
    // World units per uv unit: the depth s (uv units) becomes s * Lw in the world.
    float Lw = sqrt(max(length(T) * length(B), 1.0e-20));
#endif
#if defined(PX_HAS_TEXTURE_COORDINATES)
    // Derivatives of the un-offset uv, taken before any loop or discard (docs/techniques.md, "How
    // they fail"): every texture read at the hit uses them, so the hit's discontinuities pick no
    // wrong mip.
    vec2 uvDx = dFdx(vUv);
    vec2 uvDy = dFdy(vUv);
    // Far from the origin float uv loses the texel: trace within the tile, keep the tile apart.
    vec2 tile = floor(vUv);
    vec2 uv = vUv - tile;
    vec2 hit = uv;
#endif
#if defined(PX_HAS_HEIGHT_MAP)
    // The height level the pixel's footprint asks for, chosen before any loop.
    int footprintLevel = clamp(int(floor(textureQueryLod(pxHeightMap, vUv).x)), 0,
                               textureQueryLevels(pxHeightMap) - 1);
#endif

    float t = 0.0;
    float lightVisible = 1.0;
#if defined(PX_HAS_PARALLAX)
    mat3 toTangent = inverse(mat3(T, B, N * Lw));
    vec3 d = toTangent * (-toCamera);
    // Seen from below the tangent plane (interpolated normals near a silhouette) the view is held
    // at a grazing angle; pxBoundParallax bounds it and turns NaN into a straight-down view.
    vec2 P = pxBoundParallax(pxScale * vec2(d.x, d.y) / max(-d.z, 1.0e-4 * length(d)));
#if defined(PX_HAS_FOOTPRINT_REFERENCE)
    pxUseHeightLevel(footprintLevel); // exact on the surface the marching techniques read
#elif defined(PX_TECHNIQUE_CONE) || defined(PX_TECHNIQUE_RELAXED_CONE) || defined(PX_TECHNIQUE_PYRAMID) || defined(PX_TECHNIQUE_EXACT)
    pxUseHeightLevel(0); // the level the cone map and the pyramid describe
#else
    pxUseHeightLevel(footprintLevel);
#if defined(PX_HAS_HARDWARE_SAMPLING)
    pxUseHeightGradients(uvDx, uvDy); // the hardware picks the mip, trilinear, as in an engine
#endif
#endif
    t = pxTraceRay(uv, P);
    hit = uv + P * t;
#if defined(PX_HAS_CLAMP_WRAP)
    // Silhouettes: a ray that leaves the tile before it hits shows what lies behind the tile.
    if (hit.x < 0.0 || hit.x > 1.0 || hit.y < 0.0 || hit.y > 1.0)
        discard;
#endif
#if defined(PX_HAS_SHADOW)
    // Towards the light from the hit, on the same height level the hit was found on.
    vec3 l = toTangent * pxLightDir;
    lightVisible = l.z > 0.0 ? pxSoftShadow(hit, t, pxBoundParallax(pxScale * vec2(l.x, l.y) / l.z),
                                            pxShadowSoftness)
                             : 0.0;
#endif
#endif

#if defined(PX_HAS_SURFACE_OUTPUT)
    // What the trace found, for inspection and tests: the same layout as the trace pass. Where the
    // view meets the pixel's tangent plane more than 89 degrees from its normal (a mesh's rims,
    // where the interpolated normal turns away; past 90 there is no ray into the relief and P is
    // held at a grazing angle above), t is -2: a surface, left out of the error figures
    // (docs/meshes.md). 89 degrees is the steepest view measured anywhere (the orbit's limit).
    bool steep = dot(N, toCamera) < PX_STEEPEST_MEASURED_COS * length(toCamera);
    pxFragColor = vec4(tile + hit, steep ? -2.0 : t, float(pxFetches));
#else
#if defined(PX_HAS_NORMAL_MAP)
    vec3 m = textureGrad(pxNormalMap, hit, uvDx, uvDy).xyz * 2.0 - 1.0;
    vec3 Tn = pxSafeNormalize(T - N * dot(N, T), vec3(0.0));
    vec3 Bn = pxSafeNormalize(B - N * dot(N, B), vec3(0.0));
    // A normal map's +Y points up the image, B = dP/dv down it (docs/conventions.md §3).
    vec3 n = pxSafeNormalize(Tn * m.x - Bn * (m.y * pxNormalGreenSign) + N * m.z, N);
#elif defined(PX_HAS_HEIGHT_NORMALS)
    pxUseHeightLevel(footprintLevel);
#if defined(PX_HAS_HARDWARE_SAMPLING)
    pxUseHeightGradients(uvDx, uvDy);
#endif
#if defined(PX_HAS_SOBEL_NORMALS)
    vec2 slope = pxHeightSlopeSobel(hit);
#else
    vec2 slope = pxHeightSlopeCentral(hit);
#endif
    // The displaced surface S = P - N s Lw (1 - h) has dS/du = T + N s Lw dh/du.
    vec3 n = cross(T + N * (pxScale * Lw * slope.x), B + N * (pxScale * Lw * slope.y));
    n = pxSafeNormalize(dot(n, N) < 0.0 ? -n : n, N);
#else
    vec3 n = N;
#endif

    vec3 albedo = pxBaseColor;
#if defined(PX_HAS_ALBEDO_MAP)
    albedo *= textureGrad(pxAlbedoMap, hit, uvDx, uvDy).rgb;
#endif
    float occlusion = 1.0;
#if defined(PX_HAS_METALLIC_ROUGHNESS)
    float roughness = pxRoughness;
    float metallic = pxMetallic;
#endif
#if defined(PX_HAS_SURFACE_MAP)
    // Packed occlusion, roughness, metallic (glTF's ORM layout): absent channels hold 1.
    vec3 orm = textureGrad(pxOrmMap, hit, uvDx, uvDy).rgb;
    occlusion = orm.r;
#if defined(PX_HAS_METALLIC_ROUGHNESS)
    roughness *= orm.g;
    metallic *= orm.b;
#endif
#endif

    vec3 v = pxSafeNormalize(toCamera, N);
#if defined(PX_HAS_METALLIC_ROUGHNESS)
    vec3 color = pxMetallicRoughness(n, v, pxLightDir, albedo, roughness, metallic, occlusion,
                                     lightVisible);
#else
    vec3 color = pxBlinnPhong(n, v, pxLightDir, albedo, occlusion, lightVisible);
#endif
#if defined(PX_HAS_ENVIRONMENT)
    color = pxToneMap(color); // radiance of any range: exposed and rolled off
#endif
    pxFragColor = vec4(pxLinearToSrgb(color), 1.0);
#endif
#endif
}
