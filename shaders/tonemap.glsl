// Display mapping, mirroring engine/image/tonemap.h exactly:
//   1. exposure x = L · 2^EV;
//   2. filmic curve x(2.51x+0.03) / (x(2.43x+0.59)+0.14), clamped to [0,1];
//   3. the sRGB transfer function (IEC 61966-2-1).

float filmicCurve(float x) {
  x = max(x, 0.0);
  return clamp(x * (2.51 * x + 0.03) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0);
}

float srgbEncode(float c) {
  c = clamp(c, 0.0, 1.0);
  return c <= 0.0031308 ? 12.92 * c : 1.055 * pow(c, 1.0 / 2.4) - 0.055;
}

vec3 toneMap(vec3 radiance, float exposureEV) {
  vec3 x = radiance * exp2(exposureEV);
  return vec3(srgbEncode(filmicCurve(x.r)), srgbEncode(filmicCurve(x.g)),
              srgbEncode(filmicCurve(x.b)));
}
