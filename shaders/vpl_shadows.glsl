// Visibility of a VPL group from p (vpl.glsl asks here): a stub, every VPL visible. The VPL
// shadow maps (one cube map per group representative) replace this file.
float vplVisibility(int group, vec3 p, vec3 ng) {
  return 1.0;
}
