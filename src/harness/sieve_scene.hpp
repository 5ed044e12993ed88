#pragma once
// A scene of many caster triangles for the million-triangle runs (issue 26,
// scripts/million-triangles): a spot light above a tilted sieve over a floor.
// The sieve is 10×10 square tiles with gaps between them, so shafts pass the
// gaps and the tiles' shadows fall on the floor; each tile is a flat grid of
// quads, two triangles each, every triangle apart from its neighbours (its own
// vertices, the two of a quad 80 µm apart in height, each grown to overlap the
// others): a million separate casters, every edge a silhouette, and no light
// through a tile. (Shrunk instead, leaving hairline gaps, each view ray met
// thousands of lit gaps: docs/decisions.md "A million triangles".)
#include <filesystem>

namespace airlight::harness {

// The sieve's triangle count for `triangles` asked: 100 tiles of a×b quads,
// rounded down to a multiple of 200 (at least 200).
long sieve_triangles(long triangles);

// Writes DIR/sieve.obj (the sieve, sieve_triangles(triangles) triangles) and
// DIR/sieve.json (the scene naming it, with a box floor); returns the scene file.
std::filesystem::path write_sieve_scene(const std::filesystem::path& dir, long triangles);

}  // namespace airlight::harness
