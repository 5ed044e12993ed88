#pragma once
// Draws the viewer's image into the current draw framebuffer (display.frag.glsl):
// the pass of L_air and L_surf·T(d) the viewer shows, exposed and tone-mapped
// as `airlight render` writes a PNG.
#include "gpu/gl.hpp"

#include "core/tonemap.hpp"
#include <airlight/method.hpp>

namespace airlight::view {

class Display {
public:
  Display();  // needs the GL context current
  // Fills the viewport (x, y, width, height) with the images: pixel for pixel
  // at its size, stretched bilinearly when smaller (progressive frames).
  void draw(GLuint airlight, GLuint surface, int x, int y, int width, int height, Pass pass,
            const ToneMap& tone) const;
  // An image of display values (sRGB-encoded, e.g. a heat map) as it is.
  void draw_display_values(GLuint image, int x, int y, int width, int height) const;

private:
  void run(GLuint airlight, GLuint surface, int x, int y, int width, int height, int mode, const ToneMap& tone) const;

  gpu::VertexArray empty_;  // core profile draws need a vertex array, even with no attributes
  gpu::Sampler nearest_, bilinear_;
};

}  // namespace airlight::view
