// The environment seen through each pixel: the unfiltered level, exposed and tone-mapped as the
// mesh's light is.

in vec2 vNdc;

layout(location = 0) out vec4 pxFragColor;

void main() {
    vec4 far = pxInverseViewProjection * vec4(vNdc, 1.0, 1.0);
    vec3 d = far.xyz / far.w - pxCameraPos;
    vec3 c = textureLod(pxEnvSpecular, pxEquirectUv(d), 0.0).rgb;
    pxFragColor = vec4(pxLinearToSrgb(pxToneMap(c)), 1.0);
}
