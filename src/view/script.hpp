#pragma once
// `airlight view --script FILE`: the viewer driven by text, one command per
// line (# starts a comment), each doing what a panel or the mouse does:
//
//   method NAME                      switch method (re-create and prepare)
//   set LABEL VALUE                  the method's setting widget labelled LABEL
//   pass composite|airlight|surface  exposure X      tonemap agx|aces|clamp
//   camera orbit YAW PITCH | look YAW PITCH | fly RIGHT UP FORWARD | dolly F | fov DEG | reset
//   light I position X Y Z | direction X Y Z | cone DEG | edge DEG | intensity R G B
//   medium scattering R G B | absorption R G B | phase TYPE [G]
//   frame [N]                        render and show N frames (default 1)
//   measure N                        N frames at rest, then N orbiting: prints ms per frame
//   error off|split|heat             the error view against the reference
//   reference                        draw frames until the reference of this view is done: prints rRMSE
//   screenshot FILE                  .png tone-mapped, .exr or .pfm linear
//   window FILE                      the next frame as the window shows it, panels included (PNG)
//   save FILE                        the scene as edited, airlight-scene/1 JSON
//   quit
//
// Without `quit` the window stays open for the user once the script ends.
#include "view/viewer.hpp"

#include <filesystem>

namespace airlight::view {

// Throws InputError(file, "line N") for a line it cannot read; what the viewer
// throws (a bad value, a failed frame) propagates.
void run_script(Viewer& viewer, const std::filesystem::path& file);

}  // namespace airlight::view
