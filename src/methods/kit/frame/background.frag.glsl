// G-buffer where no surface is hit: the far-plane distance along the pixel ray
// (geometry::far_distance: the distance methods march to), no normal, no albedo.
#include "methods/kit/frame/view_ray.glsl"

layout(location = 0) out float out_distance;
layout(location = 1) out vec4 out_normal;
layout(location = 2) out vec4 out_geometric_normal;
layout(location = 3) out vec4 out_albedo;

void main() {
  out_distance = far_plane_distance(pixel_ray(gl_FragCoord.xy));
  out_normal = vec4(0.0);
  out_geometric_normal = vec4(0.0);
  out_albedo = vec4(0.0);  // a = 0: nothing hit
}
