// Light culling (engine/render/light_culling.h): the lights of the fragment's view cluster.
// Tiles are square blocks of uClusterTilePixels pixels counted from the bottom-left, as
// gl_FragCoord is; slices are exponential in the view depth d (render/cluster_grid.h):
//   slice = clamp(floor(log(d) · uClusterSlice.x + uClusterSlice.y), 0, slices − 1),
//   cluster = (slice · tilesY + tileY) · tilesX + tileX.
// Each cluster's header in the light table: (first entry, punctual count, area count); entries
// are the lights' own indices, 4 to a texel (render/light_grid.h). Off (uLightGridEnabled
// false): every light, in order.

#include "light_table.glsl"

uniform bool uLightGridEnabled;
uniform int uClustersFirst;        // light-table texel of cluster 0's header
uniform int uClusterEntriesFirst;  // light-table texel of the first 4 entries
uniform int uClusterTilePixels;
uniform ivec3 uClusterCounts;  // tiles across, tiles up, slices
uniform vec2 uClusterSlice;    // slice(d) = floor(log(d) · x + y)
uniform vec4 uViewDepthRow;    // d = dot(uViewDepthRow, (p, 1)), metres

struct LightList {
  bool all;  // culling off: every light
  int first;
  int punctualCount;
  int areaCount;
};

LightList clusterLights(vec3 p) {
  if (!uLightGridEnabled) return LightList(true, 0, 0, 0);
  ivec2 tile = min(ivec2(gl_FragCoord.xy) / uClusterTilePixels, uClusterCounts.xy - 1);
  float d = dot(uViewDepthRow, vec4(p, 1.0));
  float s = floor(log(max(d, 1e-30)) * uClusterSlice.x + uClusterSlice.y);
  int slice = int(clamp(s, 0.0, float(uClusterCounts.z - 1)));
  int cluster = (slice * uClusterCounts.y + tile.y) * uClusterCounts.x + tile.x;
  vec4 header = texelFetch(uLightTable, uClustersFirst + cluster);
  return LightList(false, int(header.x), int(header.y), int(header.z));
}

// Entry k of the lists (k counted from entry 0 of the section).
int clusterEntry(int k) {
  return int(texelFetch(uLightTable, uClusterEntriesFirst + k / 4)[k % 4]);
}

// The k-th punctual light of `list`: its index in the light table.
int punctualLightIndex(LightList list, int k) {
  return list.all ? k : clusterEntry(list.first + k);
}

// The k-th area light of `list`: its row among the area lights.
int areaLightIndex(LightList list, int k) {
  return list.all ? k : clusterEntry(list.first + list.punctualCount + k);
}
