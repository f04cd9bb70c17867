// The height map's slope (dh/du, dh/dv) in uv units at a point, for normals derived from height
// (docs/conventions.md §3: n ∝ (-s dh/du, +s dh/dv, 1) with a normal map's +Y up the image). Both
// filters are derivative estimates from bilinear samples one texel apart: on a linear ramp each
// returns the exact slope, so switching the filter never changes the strength.

// Central differences, 4 fetches (the tutorials' "medium" variant).
vec2 pxHeightSlopeCentral(vec2 uv) {
    float ex = 1.0f / float(pxMapSize.x);
    float ey = 1.0f / float(pxMapSize.y);
    float left = pxHeight(vec2(uv.x - ex, uv.y));
    float right = pxHeight(vec2(uv.x + ex, uv.y));
    float up = pxHeight(vec2(uv.x, uv.y - ey));
    float down = pxHeight(vec2(uv.x, uv.y + ey));
    return vec2((right - left) * 0.5f * float(pxMapSize.x), (down - up) * 0.5f * float(pxMapSize.y));
}

// 3x3 Sobel, 8 fetches (the centre weighs nothing): weights 1 2 1 over 8 texel-widths.
vec2 pxHeightSlopeSobel(vec2 uv) {
    float ex = 1.0f / float(pxMapSize.x);
    float ey = 1.0f / float(pxMapSize.y);
    float a = pxHeight(vec2(uv.x - ex, uv.y - ey));
    float b = pxHeight(vec2(uv.x, uv.y - ey));
    float c = pxHeight(vec2(uv.x + ex, uv.y - ey));
    float d = pxHeight(vec2(uv.x - ex, uv.y));
    float f = pxHeight(vec2(uv.x + ex, uv.y));
    float g = pxHeight(vec2(uv.x - ex, uv.y + ey));
    float h = pxHeight(vec2(uv.x, uv.y + ey));
    float k = pxHeight(vec2(uv.x + ex, uv.y + ey));
    float du = (c + 2.0f * f + k) - (a + 2.0f * d + g);
    float dv = (g + 2.0f * h + k) - (a + 2.0f * b + c);
    return vec2(du * 0.125f * float(pxMapSize.x), dv * 0.125f * float(pxMapSize.y));
}
