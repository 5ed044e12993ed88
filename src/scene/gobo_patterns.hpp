#pragma once
// Procedural light maps for the built-in scenes. Dobashi et al. 2000 store a
// light's intensity distribution as a "light map texture" (§4) and show two:
// the polka-dot effects spots of Fig. 7b and the stained-glass window of
// Fig. 8b. Texels are linear RGB in [0, 1], row 0 the top (toward gobo_up).
#include <airlight/image.hpp>
#include <array>
#include <glm/vec3.hpp>

namespace airlight::scene_gobo {

// White round dots on black, `grid`×`grid` of them on a square lattice over the
// `size`×`size` image, each of diameter `fill` × the lattice pitch (0 < fill <= 1),
// antialiased by area.
Image polka_dots(int size, int grid, float fill);

// The transmittance of the glass panes (linear RGB): ruby, cobalt, amber, emerald.
inline const std::array<glm::vec3, 4> glass_colors{
    glm::vec3(0.80f, 0.04f, 0.06f), glm::vec3(0.06f, 0.18f, 0.85f),
    glm::vec3(0.95f, 0.55f, 0.06f), glm::vec3(0.06f, 0.65f, 0.20f)};

// A stained-glass window filling the image: panes of glass_colors held by
// black lead lines and framed by a lead border, with a rose window (a ring of
// eight petals around an amber eye) in its upper part. Symmetric left to right,
// so it reads the same seen from either side. Antialiased by area.
Image stained_glass(int width, int height);

}  // namespace airlight::scene_gobo
