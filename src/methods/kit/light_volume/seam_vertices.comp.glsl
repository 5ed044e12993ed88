// The light volume mesh's cube seams (shell cubes; light_volume_mesh.glsl):
// each face's border vertices copied from the face that owns them.
#include "methods/kit/light_volume/light_volume_mesh.glsl"

// Border slot k of face `face` (6·4R items): its owner's vertex, unless it is the owner.
void seams(uint item) {
  int ring = 4 * grid, face = int(item) / ring;
  ivec2 v = border(int(item) % ring);
  ivec3 p = lattice(face, v);
  int f = owner(p);
  if (f == face) return;
  for (int s = 0; s < SURFACES; ++s)
    imageStore(vertices, ivec3(v, face + s * FACES), imageLoad(vertices, ivec3(face_coords(f, p), f + s * FACES)));
}

void main() {
  uint local = local_item();
  if (local >= uint(item_count)) return;
  uint item = uint(first_item) + local;
  seams(item);
}
