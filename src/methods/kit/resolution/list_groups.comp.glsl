// The indirect dispatch of a pixel list (pixel_list.glsl): a workgroup per
// GROUP_PIXELS pixels, LIST_ROW workgroups a row, as many rows as they fill.
#include "methods/kit/frame/pixel_list.glsl"

layout(local_size_x = 1) in;

void main() {
  uint groups = (list_groups.w + GROUP_PIXELS - 1u) / GROUP_PIXELS;
  list_groups.xyz = uvec3(min(groups, LIST_ROW), (groups + LIST_ROW - 1u) / LIST_ROW, 1u);
}
