#version 330 core
// The viewer's frame beside a reference image, in radiance before tone mapping
// (engine/render/reference_view.h says what each view shows; the two must stay equal).

uniform sampler2D uFrame;      // the renderer's resolved radiance, W/(sr·m²); row 0 at the bottom
uniform sampler2D uReference;  // the reference's radiance; row 0 at the top (as images are stored)
uniform int uView;             // 1 split, 2 difference
uniform vec2 uFrameSize;       // pixels
uniform vec2 uReferenceSize;   // pixels


out vec4 fragRadiance;

float luminance(vec3 c) {
  return dot(c, LUMINANCE_WEIGHTS);  // engine/image/luminance.h's weights
}

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  vec3 frame = texelFetch(uFrame, pixel, 0).rgb;
  // The reference texel at the same relative position, counted from the top row.
  vec2 fromTop = vec2(gl_FragCoord.x, uFrameSize.y - gl_FragCoord.y) / uFrameSize;
  ivec2 texel = clamp(ivec2(floor(fromTop * uReferenceSize)), ivec2(0), ivec2(uReferenceSize) - 1);
  vec3 reference = texelFetch(uReference, texel, 0).rgb;
  if (uView == 1) {
    fragRadiance = vec4(float(pixel.x) < floor(0.5 * uFrameSize.x) ? frame : reference, 1.0);
    return;
  }
  float l = luminance(frame), lRef = luminance(reference);
  if (l < DIFFERENCE_FLOOR && lRef < DIFFERENCE_FLOOR) {
    fragRadiance = vec4(0.0, 0.0, 0.0, 1.0);
    return;
  }
  float d = (l - lRef) / max(lRef, DIFFERENCE_FLOOR);
  float strength = min(abs(d) / DIFFERENCE_FULL_SCALE, 1.0);
  fragRadiance = vec4(d > 0.0 ? vec3(strength, 0.0, 0.0) : vec3(0.0, 0.0, strength), 1.0);
}
