#version 330 core
// Cascades of a directional light: an orthographic projection, so the rasterizer's own depth
// is already linear in metres along the light (shaders/shadow_directional.glsl); nothing to
// write but that.
void main() {}
