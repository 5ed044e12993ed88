#pragma once
// The built-in scenes (docs/design.md §4): the documents' test scenes, rebuilt
// from their descriptions (the figures did not survive), lit so that the
// airlight pass is roughly 0.05–1 W/(m²·sr) in the shaft at the default camera
// and exposure 1. One file per family; builtin_scenes.cpp names them.
#include <airlight/scene.hpp>

namespace airlight::scene_builtin {

// builtin_dobashi.cpp: Dobashi et al. 2000.
Scene teapot_spot();
Scene stage();
Scene stained_glass();

// builtin_biri.cpp: Biri et al. 2006.
Scene biri_sphere();
Scene biri_pens();
Scene biri_media();

// builtin_nilsson.cpp: Nilsson 2008.
Scene nilsson_toplight();
Scene nilsson_parallel();
Scene nilsson_multiple();

// builtin_toth.cpp: Tóth and Umenhoffer 2009.
Scene toth_hall();

// builtin_three_lights.cpp: the ray-marching issue's scene of several lights.
Scene three_lights();

}  // namespace airlight::scene_builtin
