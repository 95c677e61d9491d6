// The cost view's false colour and legend bar (engine/render/cost_view.h: costColour and
// costFalseColour draw the same on the CPU for bounce-render's PNG; the ramp and the ticks here
// must stay equal to those): black at 0, then blue, cyan, green, yellow and red at scaleMax, a
// fifth of the scale each, white beyond it.
const vec3 COST_RAMP[6] = vec3[6](vec3(0.0), vec3(0.0, 0.0, 1.0), vec3(0.0, 1.0, 1.0),
                                  vec3(0.0, 1.0, 0.0), vec3(1.0, 1.0, 0.0), vec3(1.0, 0.0, 0.0));

vec3 costColour(float c, float scaleMax) {
  if (!(c > 0.0)) return COST_RAMP[0];
  if (c > scaleMax) return vec3(1.0);
  float x = c / scaleMax * 5.0;
  int i = min(int(x), 4);
  return mix(COST_RAMP[i], COST_RAMP[i + 1], x - float(i));
}

// The legend bar over the bottom `rows` rows of a `size` image at pixel `p` (pixels from the
// bottom-left): 0 at the left to scaleMax at the right, white ticks at each quarter, a black
// rule on its top row. Returns false above the bar.
bool costLegend(ivec2 p, ivec2 size, int rows, float scaleMax, out vec3 colour) {
  if (p.y >= rows) return false;
  float at = size.x > 1 ? float(p.x) / float(size.x - 1) : 0.0;
  colour = at == 0.0 ? COST_RAMP[0] : costColour(at * scaleMax, scaleMax);
  for (int q = 0; q <= 4; ++q)
    if (p.x == (size.x - 1) * q / 4) colour = vec3(1.0);
  if (p.y == rows - 1 && rows > 1) colour = vec3(0.0);
  return true;
}
