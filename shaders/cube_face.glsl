// A depth cube stored as six layers of a 2D array (GL 3.3 core has no cube-map arrays): which
// layer a direction falls in and where. Shared by the VPL cubes (vpl_shadows.glsl) and the
// area lights' cubes (shadow_area.glsl).

// Face of GL's cube order (+X, −X, +Y, −Y, +Z, −Z) that direction d falls in (major axis), and
// d's texture coordinates in it, as cubeFaceShadowView renders the face: forward F, up U,
// lookAt's right s = F × U and up u = s × F; a 90° projection gives ndc = (s·d, u·d) / (F·d).
vec3 cubeFaceUv(vec3 d) {
  vec3 a = abs(d);
  int face;
  vec3 f, up;
  if (a.x >= a.y && a.x >= a.z) {
    face = d.x > 0.0 ? 0 : 1;
    f = vec3(sign(d.x), 0.0, 0.0);
    up = vec3(0.0, -1.0, 0.0);
  } else if (a.y >= a.z) {
    face = d.y > 0.0 ? 2 : 3;
    f = vec3(0.0, sign(d.y), 0.0);
    up = vec3(0.0, 0.0, sign(d.y));
  } else {
    face = d.z > 0.0 ? 4 : 5;
    f = vec3(0.0, 0.0, sign(d.z));
    up = vec3(0.0, -1.0, 0.0);
  }
  vec3 s = cross(f, up);
  vec3 u = cross(s, f);
  vec2 ndc = vec2(dot(s, d), dot(u, d)) / dot(f, d);
  return vec3(ndc * 0.5 + 0.5, float(face));
}
