// The linear search shared by steep, pom, relief and secant: layers evenly spaced in t from where
// the ray drops below the highest texel, as many as the view angle asks for (pxLayerCount).
// Returns the first layer at or below the surface and the layer before it, with their f values.

struct PxBracket {
    float t0; // last layer above the surface (== t1 if the first layer already hits)
    float t1; // first layer at or below it
    float f0; // f(t0) < 0 (unless t0 == t1)
    float f1; // f(t1) >= 0
};

PxBracket pxLinearSearch(vec2 uv0, vec2 P) {
    int layers = pxLayerCount(P);
    float start = pxStartT();
    float dt = (1.0f - start) / float(layers);
    PxBracket b;
    b.t0 = start;
    b.f0 = -1.0f;
    b.t1 = 1.0f;
    b.f1 = 0.0f;
    for (int k = 0; k <= layers; ++k) {
        float t = k == layers ? 1.0f : start + dt * float(k);
        float f = pxDepthGap(uv0, P, t);
        if (f >= 0.0f) {
            b.t1 = t;
            b.f1 = f;
            if (k == 0) {
                b.t0 = t;
                b.f0 = f;
            }
            return b;
        }
        b.t0 = t;
        b.f0 = f;
    }
    return b; // only NaN heights get here: t1 = 1 is still a valid answer
}

// Where the segment between two samples of f crosses zero; f0 < 0 <= f1 keeps it in [t0, t1].
float pxLinearRoot(float t0, float t1, float f0, float f1) {
    PX_PRECISE float denominator = f1 - f0;
    if (!(denominator > 0.0f))
        return t1;
    PX_PRECISE float root = t0 + (t1 - t0) * clamp(-f0 / denominator, 0.0f, 1.0f);
    return root;
}
