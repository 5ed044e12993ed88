// The direction from a cube map's centre through (s, t) ∈ [−1, 1]² of face
// `face` (GL's order +x −x +y −y +z −z): the OpenGL specification's cube map
// face selection, inverted. Shared by the import of an engine's cube maps and
// the light volume mesh.
vec3 cube_face_direction(int face, vec2 st) {
  if (face == 0) return vec3(1.0, -st.y, -st.x);
  if (face == 1) return vec3(-1.0, -st.y, st.x);
  if (face == 2) return vec3(st.x, 1.0, st.y);
  if (face == 3) return vec3(st.x, -1.0, -st.y);
  if (face == 4) return vec3(st.x, -st.y, 1.0);
  return vec3(-st.x, -st.y, -1.0);
}
