// A sparse grid's pixels (SceneFrame::use_gbuffer_grid): the indirect
// dispatch's workgroup counts, then the pixels themselves, one an invocation
// of gpu::pixel_workgroup in the order listed. A list, not the tiles that
// hold the pixels: llvmpipe runs every lane of a tile whether its pixel is
// wanted or not, and the pixels reduced resolution recomputes lie along
// edges, a few of a tile's 64. Written by methods/kit/resolution, read by
// pixel.glsl. Needs BINDING_PIXEL_LIST.
const uint LIST_ROW = 4096u;     // workgroups a row of the indirect dispatch
const uint GROUP_PIXELS = 64u;   // gpu::pixel_workgroup's invocations
#ifdef PIXEL_LIST_READONLY
readonly
#endif
layout(std430, binding = BINDING_PIXEL_LIST) buffer PixelList {
  uvec4 list_groups;  // x, y, z workgroups (list_groups.comp.glsl); w the pixels listed
  uint listed[];      // x | y << 16: a texture is far narrower than 65536 pixels
};

#ifndef PIXEL_LIST_READONLY
// Room for `count` pixels at the list's end: the index of the first.
uint list_room(uint count) { return atomicAdd(list_groups.w, count); }
void list_pixel(uint index, ivec2 pixel) { listed[index] = uint(pixel.x) | (uint(pixel.y) << 16); }
#endif

// This invocation's pixel in the list; (−1, −1) past its end.
ivec2 listed_pixel() {
  uint index = (gl_WorkGroupID.y * LIST_ROW + gl_WorkGroupID.x) * GROUP_PIXELS + gl_LocalInvocationIndex;
  if (index >= list_groups.w) return ivec2(-1);
  uint bits = listed[index];
  return ivec2(bits & 0xffffu, bits >> 16);
}
